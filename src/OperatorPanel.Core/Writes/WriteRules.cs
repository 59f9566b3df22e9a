using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Writes;

/// <summary>
/// What the panel refuses to write although the link and the CPU would take it (those are <see cref="LinkAreas"/> and
/// <see cref="AddressRules"/>), checked before anything is sent, the same for <c>opanel write</c> and the Memory window:
/// <list type="bullet">
/// <item>a byte of a tag the project marks read-only, however the write names it (VB151 inside TankLevel's VW150,
/// V150.3, VD148 across it): the project's word on a cell binds its bytes, not only its symbol. A bit the project lists
/// among its outputs stays the Output window's to switch, whatever tag shows its byte;</item>
/// <item>on a Freeport link, the V bytes of the station's handler (<see cref="HandlerProtection"/>), where the project's
/// "handlerVFirst" puts it or else at the default place: it would refuse the write with 83 after the frame went out.</item>
/// </list>
/// A writable tag whose writes these rules refuse is a contradiction in the project (<see cref="TagProblem"/>).
/// </summary>
public static class WriteRules
{
    /// <summary>Null when the project lets <paramref name="address"/> be written on <paramref name="station"/>; else why not.</summary>
    public static string? Refusal(PlcAddress address, ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(station);
        return Refusal(address, station.Link.Protocol, station.Cpu, station);
    }

    /// <summary>
    /// The same with the link and the CPU given apart from the project (<c>opanel write --ppi</c> or <c>--cpu</c> override
    /// the station's); without a <paramref name="station"/> there are no tags, and the handler is the full one at the default place.
    /// </summary>
    public static string? Refusal(PlcAddress address, LinkProtocol link, CpuProfile? cpu, ProjectStation? station)
    {
        if (station is not null && ReadOnlyTagRefusal(address, station) is { } readOnly)
        {
            return readOnly;
        }

        return link == LinkProtocol.Freeport && cpu is not null
            ? HandlerProtection.Refusal(address, cpu, station?.Compact ?? false, station?.HandlerVFirst)
            : null;
    }

    /// <summary>
    /// Null unless <paramref name="tag"/> is writable and these rules refuse writing its address on
    /// <paramref name="station"/>; then why, naming the tag, and for a read-only tag in the way that tag and the bytes they
    /// share: what <c>opanel project check</c> reports (ProjectChecks) before any write is tried.
    /// </summary>
    public static string? TagProblem(ProjectTag tag, ProjectStation station)
    {
        ArgumentNullException.ThrowIfNull(tag);
        ArgumentNullException.ThrowIfNull(station);
        if (!tag.Writable)
        {
            return null;
        }

        var name = $"tag {tag.Symbol} ({tag.Address}) is writable, but";
        if (ReadOnlyTagTouched(tag.Address, station) is { } other)
        {
            return $"{name} its {Shared(tag.Address, other.Address)} also in tag {other.Symbol} ({other.Address}), which the project marks "
                + "read-only: the panel refuses every write to it; set \"writable\": false on one of them, or move one";
        }

        return station.Link.Protocol == LinkProtocol.Freeport
            && HandlerProtection.Refusal(tag.Address, station.Cpu, station.Compact, station.HandlerVFirst) is { } own
            ? $"{name} {own}: the panel refuses every write to it; set \"writable\": false, move the tag, or move the handler "
                + "(the station's \"handlerVFirst\", which generate uses, then regenerate)"
            : null;
    }

    private static string? ReadOnlyTagRefusal(PlcAddress address, ProjectStation station)
    {
        var tag = ReadOnlyTagTouched(address, station);
        if (tag is null)
        {
            return null;
        }

        var at = tag.Address;
        var inside = at.Width != AccessWidth.Bit && address.ByteOffset >= at.ByteOffset && address.LastByte <= at.LastByte;
        var relation = address == at ? $"is part of tag {tag.Symbol}"
            : inside ? $"is part of tag {tag.Symbol} ({at})"
            : $"overlaps tag {tag.Symbol} ({at})";
        return $"{address} {relation}, which the project marks read-only";
    }

    /// <summary>The first read-only tag a write of <paramref name="address"/> may change; null when none, or when the bit is an output's.</summary>
    private static ProjectTag? ReadOnlyTagTouched(PlcAddress address, ProjectStation station) =>
        address.Width == AccessWidth.Bit && station.Outputs.Any(o => o.Address == address)
            ? null
            : station.Tags.FirstOrDefault(t => !t.Writable && Touches(address, t.Address));

    /// <summary>
    /// What a write of <paramref name="write"/> and <paramref name="tag"/> share (they touch), with its verb: "byte VB151
    /// is", "bytes VB150-VB151 are", "bit V10.1 is", "T37 is".
    /// </summary>
    private static string Shared(PlcAddress write, PlcAddress tag)
    {
        if (AreaSyntax.IsNumbered(write.Area) || AreaSyntax.IsAnalog(write.Area))
        {
            // Timers and counters are numbered, analog words even: two that touch are one.
            return $"{write} is";
        }

        if (write.Width == AccessWidth.Bit && tag.Width == AccessWidth.Bit)
        {
            return $"bit {write} is";
        }

        var (first, last) = (Math.Max(write.ByteOffset, tag.ByteOffset), Math.Min(write.LastByte, tag.LastByte));
        var prefix = AreaSyntax.Prefix(write.Area);
        return first == last
            ? string.Create(CultureInfo.InvariantCulture, $"byte {prefix}B{first} is")
            : string.Create(CultureInfo.InvariantCulture, $"bytes {prefix}B{first}-{prefix}B{last} are");
    }

    /// <summary>
    /// True when writing <paramref name="write"/> may change <paramref name="tag"/>: they share a byte, except two bits
    /// of one byte (WRITE BITS leaves the bits outside its mask as they are, docs/protocol.md "04 WRITE BITS"; a PPI bit
    /// write carries the one bit); T and C are numbered, not bytes.
    /// </summary>
    private static bool Touches(PlcAddress write, PlcAddress tag)
    {
        if (write.Area != tag.Area)
        {
            return false;
        }

        if (AreaSyntax.IsNumbered(write.Area))
        {
            return write.ByteOffset == tag.ByteOffset;
        }

        return write.Width == AccessWidth.Bit && tag.Width == AccessWidth.Bit
            ? write == tag
            : write.ByteOffset <= tag.LastByte && tag.ByteOffset <= write.LastByte;
    }
}

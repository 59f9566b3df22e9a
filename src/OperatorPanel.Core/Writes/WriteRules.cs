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
/// <item>on a Freeport link, the V bytes of the station's handler (<see cref="HandlerProtection"/>): it would refuse the
/// write with 83 after the frame went out.</item>
/// </list>
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
    /// the station's); without a <paramref name="station"/> there are no tags, and the handler is the full one.
    /// </summary>
    public static string? Refusal(PlcAddress address, LinkProtocol link, CpuProfile? cpu, ProjectStation? station)
    {
        if (station is not null && ReadOnlyTagRefusal(address, station) is { } readOnly)
        {
            return readOnly;
        }

        return link == LinkProtocol.Freeport && cpu is not null
            ? HandlerProtection.Refusal(address, cpu, station?.Compact ?? false)
            : null;
    }

    private static string? ReadOnlyTagRefusal(PlcAddress address, ProjectStation station)
    {
        if (address.Width == AccessWidth.Bit && station.Outputs.Any(o => o.Address == address))
        {
            return null;
        }

        var tag = station.Tags.FirstOrDefault(t => !t.Writable && Touches(address, t.Address));
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

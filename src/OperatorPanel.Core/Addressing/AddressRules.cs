using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Addressing;

/// <summary>
/// Checks an address against a CPU: area present, inside the area, and writable by the panel over the link when it is
/// to be written. Whether the link reads the area at all is <see cref="LinkAreas.ReadRefusal"/>'s: a read is checked
/// against the CPU only (the simulator checks its program's operands here too).
/// </summary>
public static class AddressRules
{
    /// <summary>
    /// Null when the address is fine for <paramref name="use"/> on <paramref name="cpu"/>; otherwise the reason. A write
    /// is judged for <paramref name="link"/> (Freeport unless said: it writes the fewest areas).
    /// </summary>
    public static AddressError? Check(PlcAddress address, CpuProfile cpu, AddressUse use = AddressUse.Read, LinkProtocol link = LinkProtocol.Freeport)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (AreaSyntax.IsNumbered(address.Area))
        {
            return CheckNumbered(address, cpu, use, link);
        }

        if (!cpu.TryGetArea(address.Area, out var area))
        {
            return new AddressError(AddressErrorKind.AreaNotOnCpu, $"{address}: {cpu.Name} has no {AreaName(address.Area)}");
        }

        if (address.LastByte > area.LastByte)
        {
            return new AddressError(AddressErrorKind.OutOfRange, OutOfRangeMessage(address, area, cpu));
        }

        return use == AddressUse.Write ? WriteRefusal(address, cpu, link) : null;
    }

    /// <summary>T0-T255 and C0-C255 (docs/sources/s7200-facts.md section 1); current values are never written.</summary>
    private static AddressError? CheckNumbered(PlcAddress address, CpuProfile cpu, AddressUse use, LinkProtocol link)
    {
        var (count, what) = address.Area == MemoryArea.T ? (cpu.Timers, "timer") : (cpu.Counters, "counter");
        if (address.ByteOffset >= count)
        {
            return new AddressError(AddressErrorKind.OutOfRange, $"{address} is past the last {what} {AreaSyntax.Prefix(address.Area)}{count - 1} of {cpu.Name}");
        }

        return use == AddressUse.Write ? WriteRefusal(address, cpu, link) : null;
    }

    private static AddressError? WriteRefusal(PlcAddress address, CpuProfile cpu, LinkProtocol link)
    {
        if (address.Area == MemoryArea.SM && address.ByteOffset < cpu.ReadOnlySmBytes)
        {
            return new AddressError(AddressErrorKind.NotWritable, $"{address}: SMB0-SMB{cpu.ReadOnlySmBytes - 1} are read-only system status bytes");
        }

        return LinkAreas.WriteRefusal(address, link, $"SMB{cpu.ReadOnlySmBytes} and up") is { } refusal
            ? new AddressError(AddressErrorKind.NotWritable, refusal)
            : null;
    }

    private static string OutOfRangeMessage(PlcAddress address, CpuArea area, CpuProfile cpu)
    {
        var last = LastUnit(area);
        var lastName = $"last {AreaName(address.Area, singular: true)} {last}";
        return address.Width is AccessWidth.Bit or AccessWidth.Byte || AreaSyntax.IsAnalog(address.Area)
            ? $"{address} is past the {lastName} of {cpu.Name}"
            : $"{address} ends at {AreaSyntax.Prefix(address.Area)}B{address.LastByte}, past the {lastName} of {cpu.Name}";
    }

    /// <summary>The last addressable unit as the manual writes it: VB2047, SMB549, AIW62.</summary>
    private static string LastUnit(CpuArea area) => AreaSyntax.IsAnalog(area.Area)
        ? $"{AreaSyntax.Prefix(area.Area)}W{area.ByteCount - 2}"
        : $"{AreaSyntax.Prefix(area.Area)}B{area.LastByte}";

    private static string AreaName(MemoryArea area, bool singular = false) => (area, singular) switch
    {
        (MemoryArea.AI, false) => "analog inputs (AIW)",
        (MemoryArea.AQ, false) => "analog outputs (AQW)",
        (MemoryArea.AI, true) => "analog input word",
        (MemoryArea.AQ, true) => "analog output word",
        (MemoryArea.I, true) => "input byte",
        (MemoryArea.Q, true) => "output byte",
        (MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L, true) =>
            $"{AreaSyntax.Prefix(area)} byte",
        (MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC or MemoryArea.L, false) =>
            $"{AreaSyntax.Prefix(area)} memory",
    };
}

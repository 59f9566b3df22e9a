using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Core.Addressing;

/// <summary>Checks an address against a CPU: area present, inside the area, and writable by the panel when it is to be written.</summary>
public static class AddressRules
{
    /// <summary>Null when the address is fine for <paramref name="use"/> on <paramref name="cpu"/>; otherwise the reason.</summary>
    public static AddressError? Check(PlcAddress address, CpuProfile cpu, AddressUse use = AddressUse.Read)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        if (!cpu.TryGetArea(address.Area, out var area))
        {
            return new AddressError(AddressErrorKind.AreaNotOnCpu, $"{address}: {cpu.Name} has no {AreaName(address.Area)}");
        }

        if (address.LastByte > area.LastByte)
        {
            return new AddressError(AddressErrorKind.OutOfRange, OutOfRangeMessage(address, area, cpu));
        }

        return use == AddressUse.Write ? WriteRefusal(address, cpu) : null;
    }

    /// <summary>True when the panel's link protocol can read this address (<see cref="LinkAreas.FreeportServes"/>).</summary>
    public static bool IsServedByLink(MemoryArea area) => LinkAreas.FreeportServes(area);

    private static AddressError? WriteRefusal(PlcAddress address, CpuProfile cpu) => address.Area switch
    {
        MemoryArea.I => new AddressError(AddressErrorKind.NotWritable, $"{address}: inputs are read from the field; the panel never writes them"),
        MemoryArea.AI => new AddressError(AddressErrorKind.NotWritable, $"{address}: analog inputs are read-only"),
        MemoryArea.SM when address.ByteOffset < cpu.ReadOnlySmBytes =>
            new AddressError(AddressErrorKind.NotWritable, $"{address}: SMB0-SMB{cpu.ReadOnlySmBytes - 1} are read-only system status bytes"),
        MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM => null,
        MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AQ or MemoryArea.AC or MemoryArea.HC or MemoryArea.L =>
            new AddressError(AddressErrorKind.NotWritable, $"{address}: the Freeport link writes only Q, M, V and SMB{cpu.ReadOnlySmBytes} and up"),
    };

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

using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Commands;

/// <summary>A CPU profile as opanel prints it (text and JSON share this shape).</summary>
internal sealed record CpuProfileView(
    string Model,
    string Revision,
    string Name,
    int LocalDigitalInputs,
    int LocalDigitalOutputs,
    int LocalAnalogInputs,
    int LocalAnalogOutputs,
    int MaxExpansionModules,
    int ProgramBytes,
    int ProgramBytesWithoutRunModeEdit,
    IReadOnlyList<AreaView> Areas,
    string ReadOnlySm,
    string Timers,
    string Counters,
    int HighSpeedCounters,
    int LocalBytesPerPou,
    int Subroutines,
    int InterruptRoutines,
    int CommunicationPorts,
    IReadOnlyList<BaudView> FreeportBaudRates,
    string Smb6)
{
    public static CpuProfileView From(CpuProfile p) => new(
        CpuModelNames.ShortName(p.Model),
        p.Revision.ToString(),
        p.Name,
        p.LocalDigitalInputs,
        p.LocalDigitalOutputs,
        p.LocalAnalogInputs,
        p.LocalAnalogOutputs,
        p.MaxExpansionModules,
        p.ProgramBytes,
        p.ProgramBytesWithoutRunModeEdit,
        p.Areas.Select(AreaView.From).ToList(),
        $"SMB0-SMB{p.ReadOnlySmBytes - 1}",
        $"T0-T{p.Timers - 1}",
        $"C0-C{p.Counters - 1}",
        p.HighSpeedCounters,
        p.LocalBytesPerPou,
        p.Subroutines,
        p.InterruptRoutines,
        p.CommunicationPorts,
        p.FreeportBaudRates.OrderBy(r => r.Baud).Select(r => new BaudView(r.Baud, Convert.ToString(r.Code, 2).PadLeft(3, '0'))).ToList(),
        "16#" + p.CpuIdCode.ToString("X2", CultureInfo.InvariantCulture));

    public void WriteText(TextWriter o)
    {
        o.WriteLine($"{Name} ({Revision})   SMB6 {Smb6}   ports {CommunicationPorts}   local I/O {LocalDigitalInputs} DI / {LocalDigitalOutputs} DQ"
            + (LocalAnalogInputs + LocalAnalogOutputs > 0 ? $" + {LocalAnalogInputs} AI / {LocalAnalogOutputs} AQ" : string.Empty)
            + $"   expansion modules {MaxExpansionModules}");
        o.WriteLine($"  program    {ProgramBytes} bytes with run mode edit, {ProgramBytesWithoutRunModeEdit} without");
        o.WriteLine("  areas      " + string.Join("  ", Areas.Select(a => $"{a.Area} {a.Range}")));
        o.WriteLine($"  also       {Timers}  {Counters}  HC x{HighSpeedCounters}  AC0-AC3  L {LocalBytesPerPou} bytes/POU  SBR0-SBR{Subroutines - 1}  INT0-INT{InterruptRoutines - 1}");
        o.WriteLine($"  read-only  {ReadOnlySm}, all of I and AIW");
        o.WriteLine("  freeport   " + string.Join("  ", FreeportBaudRates.Select(b => $"{b.Baud}={b.Code}")) + "  (baud=SMB30 bits 4-2)");
        o.WriteLine();
    }
}

internal sealed record AreaView(string Area, int Bytes, string Range)
{
    public static AreaView From(CpuArea a)
    {
        var prefix = PlcAddress.ForBytes(a.Area, 0, a.Area is MemoryArea.AI or MemoryArea.AQ ? AccessWidth.Word : AccessWidth.Byte).ToString();
        prefix = prefix[..^1];
        var last = a.Area is MemoryArea.AI or MemoryArea.AQ ? a.ByteCount - 2 : a.LastByte;
        return new AreaView(a.Area.ToString(), a.ByteCount, $"{prefix}0-{prefix}{last}");
    }
}

internal sealed record BaudView(int Baud, string Code);

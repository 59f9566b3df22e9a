using System.Collections.Immutable;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Diagnostics;

namespace OperatorPanel.Cli.Commands;

/// <summary>What <c>opanel generate</c> prints: the files written and, with --stats, the handler's figures; or the diagnostics.</summary>
internal static class GenerateView
{
    public static void WriteRefused(CliContext cli, ImmutableArray<StlDiagnostic> diagnostics)
    {
        if (cli.Json)
        {
            cli.WriteJson(new { ok = false, diagnostics = diagnostics.Select(d => new { id = d.Id, message = d.Message }) });
            return;
        }

        foreach (var diagnostic in diagnostics)
        {
            cli.Error.WriteLine($"opanel: {diagnostic.Id}: {diagnostic.Message}");
        }

        cli.Error.WriteLine(diagnostics.Length == 1
            ? "opanel: nothing written: the handler settings above are impossible"
            : $"opanel: nothing written: {diagnostics.Length} handler settings above are impossible");
    }

    /// <summary><paramref name="warnings"/>: the merge's warnings as JSON objects (printed on stderr already in text mode).</summary>
    public static void WriteDone(CliContext cli, List<string> files, HandlerStats stats, bool withStats, ImmutableArray<MeasuredRequest> measured, List<object> warnings)
    {
        if (cli.Json)
        {
            cli.WriteJson(new { ok = true, files, stats = withStats ? StatsJson(stats, measured) : null, warnings });
            return;
        }

        foreach (var file in files)
        {
            cli.Out.WriteLine($"wrote {file}");
        }

        if (!withStats)
        {
            return;
        }

        cli.Out.WriteLine($"V bytes reserved:       {stats.VRange} ({stats.VBytes} bytes)");
        cli.Out.WriteLine(stats.Protocol != 3
            ? $"READ CHANGES copies:    {stats.CopyRange} ({stats.CopyBytes} bytes; READ CHANGES and STOP work bytes: {stats.ChangesWorkBytes})"
            : stats.Compact ? "list:                   none (compact handler: READ only)"
            : $"list:                   up to {stats.CopyBytes} data bytes; the copy READ LIST compares with (every slot's 4-byte window) is inside the V bytes above");
        cli.Out.WriteLine($"STOP command:           {StopText(stats)}");
        WriteSize(cli, stats.Size);
        cli.Out.WriteLine($"interrupt events used:  {string.Join(", ", stats.InterruptEvents)}");
        cli.Out.WriteLine($"blocks used:            {string.Join(", ", stats.Blocks.Select(b => $"{b.Name} ({b.NumberText})"))}");
        cli.Out.WriteLine("measured in the interpreter at the manual's execution times (conservative where it has none); total ms: all the");
        cli.Out.WriteLine("handler executed for the request; scans: from the request to the slice that ends the reply's check (the reply");
        cli.Out.WriteLine(stats.Compact
            ? "leaves whole, in one XMT, when its check is done):"
            : "leaves in chunks meanwhile, from the first pass of its check on):");
        if (stats.Protocol == 3)
        {
            cli.Out.WriteLine("READ, WRITE and WRITE BITS are run on an item in each of I, Q, M and V (SM is not served); their rows show the slowest, named.");
        }

        var width = measured.Max(m => m.Name.Length);
        var unit = stats.Protocol == 3 ? "bytes" : "chars";
        cli.Out.WriteLine($"  {"request".PadRight(width)}  {unit} in -> out  instructions  total ms  worst interrupt ms  worst scan ms  scans");
        foreach (var m in measured)
        {
            cli.Out.WriteLine(FormattableString.Invariant(
                $"  {m.Name.PadRight(width)}  {m.RequestChars,8} -> {m.ReplyChars,3}  {m.Instructions,12}  {Ms(m.ExecutionTime),8}  {Ms(m.WorstInterrupt),18}  {Ms(m.WorstScan),13}  {m.Scans,5}"));
        }

        var interrupt = measured.MaxBy(m => m.WorstInterrupt)!;
        var scan = measured.MaxBy(m => m.WorstScan)!;
        cli.Out.WriteLine(FormattableString.Invariant($"worst interrupt routine: {Ms(interrupt.WorstInterrupt)} ms ({interrupt.Name})"));
        cli.Out.WriteLine(FormattableString.Invariant($"worst added to one scan: {Ms(scan.WorstScan)} ms ({scan.Name})"));
        cli.Out.WriteLine(FormattableString.Invariant($"most scans per reply:    {measured.Max(m => m.Scans)}"));
    }

    /// <summary>
    /// Text mode: the size warning on stderr as "opanel: warning STL050 ..." and a line of advice, whether or not --stats was given. Returns
    /// it as a JSON warning (the merge's shape without file and line) for the final output; none when the size is fine.
    /// </summary>
    public static List<object> WarnSize(CliContext cli, HandlerSize size)
    {
        if (size.Warning is not { } warning)
        {
            return [];
        }

        if (!cli.Json)
        {
            // Three lines: a terminal reads them whole, and no line of ours passes 400 characters.
            cli.Error.WriteLine($"opanel: warning {StlDiagnostics.ProgramMemoryTight} {size.WarningVerdict}.");
            cli.Error.WriteLine($"opanel: {HandlerSize.CompileFirstText}:");
            cli.Error.WriteLine($"opanel: {size.WarningWays}.");
        }

        return [new { id = StlDiagnostics.ProgramMemoryTight, severity = "warning", message = warning }];
    }

    private static void WriteSize(CliContext cli, HandlerSize size)
    {
        cli.Out.WriteLine($"instructions generated: {size.Instructions} in {size.Networks} networks");
        cli.Out.WriteLine($"program size estimated: {size.EstimateText}");
        cli.Out.WriteLine($"                        {HandlerSize.BasisText}");
        cli.Out.WriteLine($"program memory:         {size.ProgramMemoryText}");
        cli.Out.WriteLine($"for comparison:         {HandlerSize.ModbusComparisonText}");
    }

    private static string Ms(TimeSpan time) => time.TotalMilliseconds.ToString("0.000", System.Globalization.CultureInfo.InvariantCulture);

    private static MeasuredRequest Worst(ImmutableArray<MeasuredRequest> measured) => measured.MaxBy(m => m.ExecutionTime)!;

    private static long Us(TimeSpan time) => (long)Math.Round(time.TotalMicroseconds);

    private static object StatsJson(HandlerStats stats, ImmutableArray<MeasuredRequest> measured) => new
    {
        firstVByte = stats.FirstVByte,
        lastVByte = stats.LastVByte,
        vBytes = stats.VBytes,
        instructions = stats.Instructions,
        networks = stats.Size.Networks,
        programBytesLow = stats.Size.LowBytes,
        programBytesHigh = stats.Size.HighBytes,
        bytesPerInstructionLow = HandlerSize.LowBytesPerInstruction,
        bytesPerInstructionHigh = HandlerSize.HighBytesPerInstruction,
        programBytesBasis = HandlerSize.BasisText,
        cpuProgramBytes = stats.Size.ProgramMemoryBytes,
        cpuProgramBytesWithoutRunModeEdit = stats.Size.Cpu.ProgramBytesWithoutRunModeEdit,
        exceedsHalfOfProgramMemory = stats.Size.ExceedsHalfOfProgramMemory,
        modbusSlaveProgramBytes = HandlerSize.ModbusSlaveProgramBytes,
        modbusSlaveVBytes = HandlerSize.ModbusSlaveVBytes,
        copyBytes = stats.CopyBytes,
        changesWorkBytes = stats.ChangesWorkBytes,
        stopEnabled = stats.StopEnabled,
        port = stats.Port,
        interruptEvents = stats.InterruptEvents,
        blocks = stats.Blocks.Select(b => new { name = b.Name, block = b.NumberText, purpose = b.Purpose }),
        measured = measured.Select(m => new
        {
            request = m.Name,
            requestChars = m.RequestChars,
            replyChars = m.ReplyChars,
            instructions = m.Instructions,
            microseconds = Us(m.ExecutionTime),
            worstInterruptMicroseconds = Us(m.WorstInterrupt),
            worstScanMicroseconds = Us(m.WorstScan),
            scans = m.Scans,
        }),
        worstInstructions = measured.Max(m => m.Instructions),
        worstMicroseconds = Us(Worst(measured).ExecutionTime),
        worstInterruptMicroseconds = Us(measured.Max(m => m.WorstInterrupt)),
        worstScanMicroseconds = Us(measured.Max(m => m.WorstScan)),
        mostScansPerReply = measured.Max(m => m.Scans),
    };

    /// <summary>v2's STOP is 07 (refused with 05 when left out); v3's is 08 (85, an unknown command, when left out or in a compact handler).</summary>
    private static string StopText(HandlerStats stats) => (stats.Protocol, stats.StopEnabled) switch
    {
        (3, true) => "enabled (08 STOP puts the CPU in STOP after its reply)",
        (3, false) => stats.Compact ? "not included: a compact handler has none (08 gets 85)" : "not included (08 gets 85)",
        (_, true) => "enabled (07 STOP puts the CPU in STOP after its reply)",
        _ => "not included (07 gets error 05)",
    };
}

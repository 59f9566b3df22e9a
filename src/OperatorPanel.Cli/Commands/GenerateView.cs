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
        cli.Out.WriteLine($"instructions generated: {stats.Instructions}");
        cli.Out.WriteLine($"interrupt events used:  {string.Join(", ", stats.InterruptEvents)}");
        cli.Out.WriteLine($"blocks used:            {string.Join(", ", stats.Blocks.Select(b => $"{b.Name} ({b.NumberText})"))}");
        cli.Out.WriteLine("measured in the interpreter (instructions in the handler's interrupt routines, added to the scan; times estimated):");
        foreach (var m in measured)
        {
            cli.Out.WriteLine(FormattableString.Invariant($"  {m.Name,-24} {m.RequestChars,3} -> {m.ReplyChars,3} chars  {m.Instructions,5} instructions  {m.ExecutionTime.TotalMilliseconds,7:0.000} ms"));
        }

        var worst = Worst(measured);
        cli.Out.WriteLine(FormattableString.Invariant($"worst case per request:  {worst.Instructions} instructions, {worst.ExecutionTime.TotalMilliseconds:0.000} ms ({worst.Name})"));
    }

    private static MeasuredRequest Worst(ImmutableArray<MeasuredRequest> measured) => measured.MaxBy(m => m.ExecutionTime)!;

    private static object StatsJson(HandlerStats stats, ImmutableArray<MeasuredRequest> measured) => new
    {
        firstVByte = stats.FirstVByte,
        lastVByte = stats.LastVByte,
        vBytes = stats.VBytes,
        instructions = stats.Instructions,
        port = stats.Port,
        interruptEvents = stats.InterruptEvents,
        blocks = stats.Blocks.Select(b => new { name = b.Name, block = b.NumberText, purpose = b.Purpose }),
        measured = measured.Select(m => new { request = m.Name, requestChars = m.RequestChars, replyChars = m.ReplyChars, instructions = m.Instructions, microseconds = (long)Math.Round(m.ExecutionTime.TotalMicroseconds) }),
        worstInstructions = measured.Max(m => m.Instructions),
        worstMicroseconds = (long)Math.Round(Worst(measured).ExecutionTime.TotalMicroseconds),
    };
}

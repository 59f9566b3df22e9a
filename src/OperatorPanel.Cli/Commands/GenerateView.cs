using System.Collections.Immutable;
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

    public static void WriteDone(CliContext cli, List<string> files, HandlerStats stats, bool withStats)
    {
        if (cli.Json)
        {
            cli.WriteJson(new { ok = true, files, stats = withStats ? StatsJson(stats) : null });
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
    }

    private static object StatsJson(HandlerStats stats) => new
    {
        firstVByte = stats.FirstVByte,
        lastVByte = stats.LastVByte,
        vBytes = stats.VBytes,
        instructions = stats.Instructions,
        port = stats.Port,
        interruptEvents = stats.InterruptEvents,
        blocks = stats.Blocks.Select(b => new { name = b.Name, block = b.NumberText, purpose = b.Purpose }),
    };
}

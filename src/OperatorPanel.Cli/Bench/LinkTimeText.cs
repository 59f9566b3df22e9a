using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Cli.Bench;

/// <summary>Prints the time model: its inputs with their sources, each exchange part by part, the cycle totals.</summary>
internal static class LinkTimeText
{
    public static void Write(TextWriter o, LinkTimeReport report, ImmutableArray<string> handlerProblems)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(report);
        var m = report.Model;
        o.WriteLine(Invariant($"Time model (MODELLED, not measured): {report.Medium}, {m.Line}, character {m.Line.CharacterMs:0.###} ms"));
        o.WriteLine("  handler       the generated handler run in the STL interpreter at the published instruction times");
        o.WriteLine("                (StlTiming: System Manual tables, conservative where none), served this refresh's requests in order;");
        o.WriteLine("                the reply's first character and its '>' timed on the simulated port (simulated time)");
        o.WriteLine(Invariant($"  user program  {m.ProgramScanMs:0.###} ms per scan (assumed; --scan-ms), run in the interpreter after the handler's call"));
        o.WriteLine(Invariant($"  reply delay   {m.ReplyDelayMs:0.###} ms after the first pass of the reply's check (timed interrupt 0); the reply leaves in chunks"));
        o.WriteLine("                while the check goes on, so it may pause between characters");
        o.WriteLine(Invariant($"  turnaround    PC/PPI cable {m.TurnaroundMs:0.###} ms after the request (no primary source: the larger remembered figure, s7200-facts 7)"));
        o.WriteLine(Invariant($"  link gap      {m.GapMs:0.###} ms after each reply (the link's gap, at least 5 ms and 3 characters: docs/protocol-v2.md)"));
        if (m.Radio is { } radio)
        {
            o.WriteLine($"  radio         {radio}");
            o.WriteLine("                store-and-forward: each module receives a frame whole before sending it on, both directions");
            o.WriteLine("                FT232R latency timer: FTDI AN232B-04; CC1100 TX start: CC1101 data sheet SWRS061I Table 34");
        }
        else
        {
            o.WriteLine(Invariant($"  PC UART       reply end reaches the PC {CableTiming.FifoTimeoutCharacters} characters late (16550 FIFO timeout, TI TL16C550C data sheet)"));
        }

        foreach (var problem in handlerProblems)
        {
            o.WriteLine($"  NOTE {problem}");
        }

        foreach (var cycle in new[] { report.Steady, report.Idle })
        {
            o.WriteLine();
            o.WriteLine(Invariant($"  {cycle.Name}: {cycle.Exchanges.Length} exchanges, {cycle.Chars} characters, {cycle.TotalMs:0.0} ms"));
            foreach (var exchange in cycle.Exchanges)
            {
                o.WriteLine(Invariant($"    {exchange.Name}: {exchange.RequestChars} + {exchange.ReplyChars} characters, {exchange.TotalMs:0.0} ms (handler {exchange.Handler.Source})"));
                foreach (var part in exchange.Parts)
                {
                    o.WriteLine(Invariant($"      {part.Ms,8:0.00} ms  {part.What}"));
                }
            }
        }

        o.WriteLine();
        o.WriteLine(Invariant($"  hex bound: {report.HexBoundChars} characters (the distinct data bytes as hex, nothing else) = {report.HexBoundMs:0.0} ms"));
    }

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}

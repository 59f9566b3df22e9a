using System.Globalization;
using OperatorPanel.Simulator.Stl;

namespace OperatorPanel.Cli.Bench.V3;

/// <summary>Prints `bench link --protocol 3`: the model's inputs, the list, each exchange part by part, the floors and goals.</summary>
internal static class V3LinkText
{
    public static void Write(TextWriter o, V3LinkReport report)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(report);
        var m = report.Model;
        var list = report.Frames.List;
        o.WriteLine("Reference line, protocol 3 (docs/protocol.md), MODELLED: the generated v3 handler run in the STL interpreter");
        o.WriteLine(Invariant($"  list          one DEFINE LIST of {list.Items.Length} slots, {list.DataBytes} data bytes ({report.BinaryBoundBytes} distinct data bytes, SMB6 fillers to a whole group); {report.Frames.FramesLeftOut} plan frames left out"));
        o.WriteLine(Invariant($"  medium        {report.Medium}, {m.Line}, byte {m.Line.CharacterMs:0.###} ms"));
        o.WriteLine(Invariant($"  user program  {m.ProgramScanMs:0.###} ms per scan (assumed; --scan-ms), run in the interpreter after the handler's call"));
        o.WriteLine(Invariant($"  end timer     END_TIMEOUT_MS {report.EndTimeoutMs} ms: RCV ends the request after it (SMW92), the reply's earliest start"));
        o.WriteLine(Invariant($"  turnaround    PC/PPI cable {m.TurnaroundMs:0.###} ms after the request (no primary source: the larger remembered figure, s7200-facts 7)"));
        o.WriteLine(Invariant($"  link gap      {m.GapMs:0.###} ms after each reply (the link's gap, at least 5 ms and 3 bytes)"));
        if (m.Radio is { } radio)
        {
            o.WriteLine($"  radio         {radio}");
            o.WriteLine("                each module forwards a frame once Core's Reader has it whole by its LEN (docs/protocol.md 1.6),");
            o.WriteLine(Invariant($"                and drops a partial frame after an idle line over {LenRuleForwarder.PartialFrameDropMs} ms (longer than any chunk pause of a scan up to that)"));
        }
        else
        {
            o.WriteLine(Invariant($"  PC UART       reply end reaches the PC {CableTiming.FifoTimeoutCharacters} bytes late (16550 FIFO timeout, TI TL16C550C data sheet)"));
        }

        foreach (var problem in report.Problems)
        {
            o.WriteLine($"  NOTE {problem}");
        }

        foreach (var (name, exchange, floor, stats) in new[]
        {
            ("steady (every value read in full)", report.Steady, report.Floors.Steady, report.Stats.Steady),
            ("idle (nothing changed)", report.Idle, report.Floors.Idle, report.Stats.Idle),
        })
        {
            o.WriteLine();
            o.WriteLine(Invariant($"  {name}: 1 exchange, {exchange.Chars} bytes, {exchange.TotalMs:0.0} ms"));
            o.WriteLine(Invariant($"    {exchange.Name}: {exchange.RequestChars} + {exchange.ReplyChars} bytes"));
            foreach (var part in exchange.Parts)
            {
                o.WriteLine(Invariant($"      {part.Ms,8:0.00} ms  {part.What}"));
            }

            o.WriteLine(Invariant($"    handler alone (generate --stats --protocol 3): {Stats(stats)}"));
            o.WriteLine(Invariant($"    a PLC taking no time: {floor.TotalMs:0.0} ms (the wire {exchange.Chars * m.Line.CharacterMs:0.0} ms, the rest end timer, PC and gap)"));
        }

        o.WriteLine();
        o.WriteLine(Invariant($"  binary bound: {report.BinaryBoundBytes} bytes (the distinct data bytes as bare bytes, nothing else) = {report.BinaryBoundMs:0.0} ms"));
        var steadyGoal = V3LinkReport.SteadyGoalRatio * report.BinaryBoundMs;
        o.WriteLine("Goals for the reference line (protocol 3):");
        o.WriteLine(Invariant($"  steady <= {V3LinkReport.SteadyGoalRatio:0.0} x binary bound = {steadyGoal:0.0} ms: {report.Steady.TotalMs:0.0} ms, {Verdict(report.Steady.TotalMs <= steadyGoal)} (a PLC taking no time: {report.Floors.Steady.TotalMs:0.0} ms)"));
        o.WriteLine(Invariant($"  idle <= {V3LinkReport.IdleGoalMs:0} ms: {report.Idle.TotalMs:0.0} ms, {Verdict(report.Idle.TotalMs <= V3LinkReport.IdleGoalMs)} (a PLC taking no time: {report.Floors.Idle.TotalMs:0.0} ms)"));
    }

    private static string Stats(MeasuredRequest? stats) => stats is null
        ? "not measured"
        : Invariant($"{stats.ExecutionTime.TotalMilliseconds:0.00} ms PLC time, {stats.Scans} scans, {stats.Instructions} instructions");

    private static string Verdict(bool met) => met ? "met" : "NOT MET";

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}

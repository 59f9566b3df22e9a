using System.Globalization;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Ppi.S7;

namespace OperatorPanel.Cli.Bench;

/// <summary>Prints the PPI bench (<c>opanel bench link --ppi</c>): the line, the PPI jobs, the model's parts and sources, the figures.</summary>
internal static class PpiBenchText
{
    public static void Write(TextWriter o, PpiBenchReport report)
    {
        ArgumentNullException.ThrowIfNull(o);
        ArgumentNullException.ThrowIfNull(report);
        var line = report.Line;
        o.WriteLine($"opanel bench link --ppi: a refresh of the reference line over PPI at {report.Baud} baud 8E1 (MODELLED by simulation)");
        o.WriteLine();
        o.WriteLine($"Reference line: {line.Cpu.Name} ({line.Cpu.Revision}), PPI address {line.Station.Address}, no handler; "
            + $"watched {line.Tags.Length} items holding {line.DistinctDataBytes} distinct data bytes");
        var plan = report.Plan;
        o.WriteLine($"PPI plan (PpiReadPlanner, PDU {PpiLimits.DefaultPduSize} bytes, gaps up to {PpiLimits.Default.BridgeGap} bytes bridged): "
            + $"{plan.Requests.Length} read job{(plan.Requests.Length == 1 ? string.Empty : "s")}, {plan.DataBytes} data bytes");
        for (var i = 0; i < plan.Requests.Length; i++)
        {
            var request = plan.Requests[i];
            o.WriteLine(Invariant($"  job {i + 1}: {request.Items.Length} items, request PDU {request.RequestPduLength} bytes ({request.RequestPduLength + 9} characters), ")
                + Invariant($"answer PDU {request.AnswerPduLength} bytes ({request.AnswerPduLength + 9} characters): {string.Join(", ", request.Items.Select(Describe))}"));
        }

        o.WriteLine();
        o.WriteLine("Each job: request (SD2) -> E5 -> poll (SD1, 6 characters) -> E5 while the CPU's scan has not reached its");
        o.WriteLine("communication phase, poll again -> the answer (SD2). Parts:");
        var character = 11 * 1000.0 / report.Baud;
        o.WriteLine(Invariant($"  characters             11 bits (start, 8 data, even parity, stop): {character:0.###} ms each (ML801761 p. 228)"));
        o.WriteLine(Invariant($"  pause before a frame   33 bit times, PROFIBUS's synchronisation pause: {33 * 1000.0 / report.Baud:0.###} ms (felser.ch)"));
        o.WriteLine(Invariant($"  CPU's station delay    11 bit times (PROFIBUS default min TSDR; unconfirmed for the S7-200), raised to the cable's turnaround: {Math.Max(11 * 1000.0 / report.Baud, report.Pc.TurnaroundMs):0.###} ms"));
        o.WriteLine(Invariant($"  CPU's answer           prepared in the communication phase of its scan (C233-01 p. 4-23): user program {report.ScanMs:0.###} ms per scan (an assumption, --scan-ms) + 0.25 ms housekeeping"));
        o.WriteLine(Invariant($"  PC side                {report.Pc.Name}: write {report.Pc.WriteLatencyMs:0.###} ms, receive +{report.Pc.ReceiveLatencyMs:0.###} ms, turnaround {report.Pc.TurnaroundMs:0.###} ms"));
        o.WriteLine();
        var r = report.Refreshes;
        o.WriteLine(Invariant($"Per refresh ({r.Length} run back to back): mean {report.SteadyMs:0.0} ms (min {r.Min(x => x.Ms):0.0}, max {r.Max(x => x.Ms):0.0}), ")
            + Invariant($"{report.SteadyChars} characters, {r.Average(x => x.EmptyPolls):0.0} polls answered E5"));
        o.WriteLine(Invariant($"Hex bound (the Freeport bench's yardstick): {report.HexBoundChars} characters at 9600 8N1 = {report.HexBoundMs:0.0} ms; ")
            + "PPI reads every value each time, so idle = steady");
        o.WriteLine();
        o.WriteLine(report.SummaryLine);
    }

    private static string Describe(S7Item item) =>
        item.DataLength == 1 ? $"{item.Area}B{item.ByteOffset}" : $"{item.Area}B{item.ByteOffset}-{item.Area}B{item.ByteOffset + item.DataLength - 1}";

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}

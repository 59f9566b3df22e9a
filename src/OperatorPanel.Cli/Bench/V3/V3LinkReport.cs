using System.Collections.Immutable;
using System.Globalization;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Handlers;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.Cli.Bench.V3;

/// <summary>
/// `opanel bench link --protocol 3`: the reference line's v3 refresh on the chosen medium (docs/bench.md, "Protocol 3").
/// The generated v3 handler serves the panel's frames in the interpreter with the user's program per scan
/// (<see cref="HandlerProbe"/>), so each exchange's PLC side is the simulated port's timeline; beside it the handler's
/// own PLC time and scans as `generate --stats --protocol 3` measures them (<see cref="V3Measurement"/>), and what a PLC
/// taking no time would allow (<see cref="Floors"/>). Against the binary bound: the distinct data bytes as bare bytes.
/// </summary>
internal sealed record V3LinkReport(
    string Medium,
    LinkTimeModel Model,
    int EndTimeoutMs,
    V3RefreshFrames Frames,
    ExchangeTime Steady,
    ExchangeTime Idle,
    (ExchangeTime Steady, ExchangeTime Idle) Floors,
    (MeasuredRequest? Steady, MeasuredRequest? Idle) Stats,
    int BinaryBoundBytes,
    ImmutableArray<string> Problems)
{
    /// <summary>Issue 23's goals: a steady refresh in at most 1.5 x the binary bound, an idle one in at most 40 ms.</summary>
    public const double SteadyGoalRatio = 1.5;

    public const double IdleGoalMs = 40;

    public double BinaryBoundMs => BinaryBoundBytes * Model.Line.CharacterMs;

    public double SteadyRatio => Steady.TotalMs / BinaryBoundMs;

    /// <summary>The one-line summary: "bench link: steady N bytes, T ms, R x binary bound; idle N bytes, T ms".</summary>
    public string SummaryLine => string.Create(
        CultureInfo.InvariantCulture,
        $"bench link: steady {Steady.Chars} bytes, {Steady.TotalMs:0.0} ms, {SteadyRatio:0.00} x binary bound; idle {Idle.Chars} bytes, {Idle.TotalMs:0.0} ms");

    public static bool TryCreate(BenchLine line, LinkTimeModel model, out V3LinkReport report, out string error)
    {
        ArgumentNullException.ThrowIfNull(line);
        ArgumentNullException.ThrowIfNull(model);
        report = null!;
        var settings = model.Line.Settings;
        if (!V3RefreshFrames.TryCreate(line, out var frames, out error)
            || !HandlerProbe.TryCreateV3(line.Cpu, line.Station, settings, TimeSpan.FromMilliseconds(model.ProgramScanMs), out var probe, out error))
        {
            return false;
        }

        var endTimeoutMs = new HandlerOptions { Cpu = line.Cpu, BaudRate = settings.Baud, Parity = settings.Parity, DataBits = settings.DataBits, Protocol = 3 }.EffectiveEndTimeoutMs;
        var problems = new List<string>();
        ExchangeTime? Serve(V3PlannedExchange planned, ref string failed)
        {
            if (!probe!.TryServe(planned.Request, out var cost, out var replyBytes, out var why))
            {
                failed = $"{planned.Name}: {why}";
                return null;
            }

            if (replyBytes != planned.ReplyBytes)
            {
                problems.Add($"{planned.Name}: the handler answered {replyBytes} bytes, Codec sizes the reply at {planned.ReplyBytes}");
            }

            // Timed only as what it is: a reply the PC would not take (docs/protocol.md section 8, rule 2) is a problem.
            if (!Codec.TryDecodeReplyTo([.. probe.LastReply.Select(r => r.Value)], planned.Request, out _, out var decode))
            {
                problems.Add($"{planned.Name}: the PC would not take the handler's reply ({decode})");
            }

            return V3ExchangeTimes.Of(model, endTimeoutMs, planned, cost!, probe.LastReply, problems);
        }

        var exchanges = new List<ExchangeTime?>();
        foreach (var planned in (IEnumerable<V3PlannedExchange>)[.. frames.Setup, frames.Steady, frames.FillCopy, frames.Idle])
        {
            exchanges.Add(Serve(planned, ref error));
            if (exchanges[^1] is null)
            {
                return false;
            }
        }

        ListPlan.TryMake(V3Measurement.ReferenceLine, HandlerShape.Full, ListPlan.AreaBytesOf(line.Cpu), out var statsList);
        // The same slots, maybe in another order (the planner orders the areas its own way): the same work per slot.
        static IEnumerable<string> Slots(ListPlan plan) => plan.Items.Select(i => $"{i.Area}{i.Offset}/{i.Length}").Order(StringComparer.Ordinal);
        if (!Slots(statsList).SequenceEqual(Slots(frames.List)))
        {
            problems.Add("the list generate --stats measures (V3Measurement.ReferenceLine) holds other slots than the panel's list for this line");
        }

        var stats = V3Measurement.TryMeasure(probe!.AwlText, line.Cpu, 0, line.Station, settings, HandlerShape.Full, out var measured, out var statsError)
            ? (measured.FirstOrDefault(m => m.Name == V3Measurement.SteadyName), measured.FirstOrDefault(m => m.Name == V3Measurement.IdleRefreshName))
            : (null, null);
        if (stats.Item1 is null)
        {
            problems.Add($"generate --stats' measurement did not run: {statsError}");
        }

        var floors = (V3ExchangeTimes.Floor(model, endTimeoutMs, frames.Steady), V3ExchangeTimes.Floor(model, endTimeoutMs, frames.Idle));
        var medium = model.Radio is null ? "PC/PPI cable" : "radio modules";
        var steady = exchanges[frames.Setup.Length]!;
        report = new V3LinkReport(
            medium, model, endTimeoutMs, frames, steady, exchanges[^1]!, floors, stats, TrafficModels.LowerBoundAsBinary(line).TotalChars, [.. problems]);
        return true;
    }
}

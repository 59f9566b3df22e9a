using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Handlers;

/// <summary>
/// Measures a v3 handler by running it (docs/protocol.md section 6; docs/bench.md): the worst case of each request
/// kind (the largest READ and WRITE, a list of every slot, a READ LIST of it whole, unchanged, with one change, with
/// the most entries, with too many) and the reference line's list (docs/bench.md: 26 ranges, 74 data bytes) read whole
/// (a steady refresh) and unchanged (an idle one), at the StlTiming figures.
/// </summary>
public static class V3Measurement
{
    public const string IdleName = "no request (a scan)";
    public const string SteadyName = "reference line: READ LIST FULL (steady)";
    public const string IdleRefreshName = "reference line: READ LIST unchanged (idle)";

    /// <summary>The reference line's data (docs/bench.md): IB0-IB2, QB0-QB1, 10 recipe, 6 counter and 7 setpoint ranges in V, MB0-MB17.</summary>
    public static ImmutableArray<ReadItem> ReferenceLine { get; } =
    [
        new(ProtocolArea.I, 0, 3), new(ProtocolArea.Q, 0, 2),
        new(ProtocolArea.V, 100, 2), new(ProtocolArea.V, 104, 4), new(ProtocolArea.V, 112, 4), new(ProtocolArea.V, 120, 2), new(ProtocolArea.V, 124, 1),
        new(ProtocolArea.V, 130, 1), new(ProtocolArea.V, 140, 4), new(ProtocolArea.V, 150, 2), new(ProtocolArea.V, 170, 1), new(ProtocolArea.V, 180, 1),
        new(ProtocolArea.V, 400, 4), new(ProtocolArea.V, 408, 4), new(ProtocolArea.V, 420, 2), new(ProtocolArea.V, 430, 1), new(ProtocolArea.V, 440, 1),
        new(ProtocolArea.V, 456, 2),
        new(ProtocolArea.V, 1000, 2), new(ProtocolArea.V, 1004, 4), new(ProtocolArea.V, 1012, 2), new(ProtocolArea.V, 1020, 1), new(ProtocolArea.V, 1024, 1),
        new(ProtocolArea.V, 1030, 4), new(ProtocolArea.V, 1040, 1),
        new(ProtocolArea.M, 0, 18),
    ];

    public static bool TryMeasure(string awlText, CpuProfile cpu, int port, Station station, LineSettings line, HandlerShape shape, out ImmutableArray<MeasuredRequest> requests, out string error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        ArgumentNullException.ThrowIfNull(shape);
        var load = StlProgramLoader.Load(awlText, cpu);
        if (load.Program is null)
        {
            (requests, error) = ([], string.Join("; ", load.Diagnostics));
            return false;
        }

        var plc = new StlPlc(load.Program);
        var freeport = new FreeportPort(port, plc.Memory, cpu, line);
        plc.AttachPort(freeport);
        var run = new HandlerRun(plc, freeport, line, port);
        var builder = ImmutableArray.CreateBuilder<MeasuredRequest>();
        builder.Add(run.Idle(IdleName));
        byte sequence = 0;
        byte Next() => sequence = (byte)((sequence + 1) % Limits.SequenceCount);
        foreach (var (name, request, poke) in Requests(station, shape, ListPlan.AreaBytesOf(cpu), Next))
        {
            poke?.Invoke(plc.Memory);
            var served = run.Serve(name ?? string.Empty, Codec.Encode(request));
            if (Environment.GetEnvironmentVariable("OPANEL_V3_TRACE") is { } trace && name is not null && name.Contains(trace, StringComparison.Ordinal))
            {
                Console.Error.WriteLine($"{name}: " + string.Join(" ", run.LastScans.Select(x => $"{x.Instructions}/{x.Time.TotalMilliseconds:F2}")));
            }

            if (name is not null)
            {
                builder.Add(served);
            }
        }

        (requests, error) = (Slowest(builder), plc.Fault is { } fault ? $"the handler faulted: {fault}" : string.Empty);
        return plc.Fault is null;
    }

    private static IEnumerable<(string? Name, Request Request, Action<PlcMemory>? Poke)> Requests(Station s, HandlerShape shape, Func<ProtocolArea, int> areaBytes, Func<byte> next)
    {
        yield return ("IDENTIFY", Request.Identify(s, next()), null);

        // READ, WRITE and WRITE BITS in every area: the item check finds the area by tests in turn and the write checks
        // refuse I, so each area takes its own time; the row keeps the slowest (Slowest). An SM item is refused, 82.
        foreach (var area in Areas)
        {
            yield return (AreaVariant($"READ {HandlerShape.MaxData} bytes", area, 0), Request.Read(s, next(), new ReadItem(area, 0, HandlerShape.MaxData)), null);
        }

        foreach (var area in Areas)
        {
            yield return (AreaVariant($"WRITE {HandlerShape.MaxData} bytes", area, 0), Request.Write(s, next(), area, 0, [.. Enumerable.Range(0, HandlerShape.MaxData).Select(i => (byte)i)]), null);
        }

        foreach (var area in Areas)
        {
            yield return (AreaVariant("WRITE BITS", area, 10), Request.WriteBits(s, next(), area, 10, 0x0F, 0x05), null);
        }

        var bad = Request.Identify(s, next());
        yield return ("another station's request", bad with { Station = new Station((s.Address % 126) + 1) }, null);
        if (!shape.HasList)
        {
            yield break;
        }

        // The slowest item check (Q, the last area tried), then the longest list: every slot a 4-byte item.
        yield return ($"DEFINE LIST {shape.ListItems} Q items", Request.DefineList(s, next(), Enumerable.Repeat(new ReadItem(ProtocolArea.Q, 0, HandlerShape.ItemBytes), shape.ListItems)), null);
        var longest = Enumerable.Range(0, shape.ListItems).Select(i => new ReadItem(ProtocolArea.V, 200 + (i * 5), HandlerShape.ItemBytes)).ToArray();
        ListPlan.TryMake(longest, shape, areaBytes, out var plan);
        yield return ($"DEFINE LIST {plan.Items.Length} items", plan.Request(s, next()), null);
        yield return ($"READ LIST FULL {plan.DataBytes} bytes", Request.ReadListFull(s, next()), null);
        yield return ($"READ LIST {plan.Items.Length} slots, copy first", Request.ReadList(s, next()), null);
        yield return ($"READ LIST {plan.Items.Length} slots unchanged", Request.ReadList(s, next()), null);
        yield return ("READ LIST 1 changed", Request.ReadList(s, next()), m => m.V[200] ^= 0xFF);
        yield return ("READ LIST 25 changed", Request.ReadList(s, next()), m => Change(m, longest.Take(25)));
        yield return ("READ LIST 26 changed (whole)", Request.ReadList(s, next()), m => Change(m, longest.Take(26)));

        // The reference line's list (docs/bench.md).
        ListPlan.TryMake(ReferenceLine, shape, areaBytes, out var line);
        yield return (null, line.Request(s, next()), null);
        yield return (null, Request.ReadListFull(s, next()), null);
        yield return (SteadyName, Request.ReadListFull(s, next()), null);
        yield return (null, Request.ReadList(s, next()), null);
        yield return (IdleRefreshName, Request.ReadList(s, next()), null);
    }

    /// <summary>The areas the handler serves (no SM: docs/protocol.md section 1.3).</summary>
    private static readonly ProtocolArea[] Areas = [ProtocolArea.I, ProtocolArea.Q, ProtocolArea.M, ProtocolArea.V];

    /// <summary>Separates a row's name from the area it was measured in, until <see cref="Slowest"/> keeps one per row.</summary>
    private const char AreaMark = '|';

    private static string AreaVariant(string row, ProtocolArea area, int offset) => $"{row}{AreaMark}{area}B{offset}";

    /// <summary>
    /// One row per request kind: of the area variants (<see cref="AreaVariant"/>) the one that adds most to a scan (then
    /// the longest in all), named "READ 16 bytes, QB0", in the place of the first.
    /// </summary>
    private static ImmutableArray<MeasuredRequest> Slowest(IEnumerable<MeasuredRequest> measured)
    {
        var rows = ImmutableArray.CreateBuilder<MeasuredRequest>();
        foreach (var group in measured.GroupBy(m => m.Name.Split(AreaMark)[0]))
        {
            var slowest = group.OrderByDescending(m => m.WorstScan).ThenByDescending(m => m.ExecutionTime).First();
            var parts = slowest.Name.Split(AreaMark);
            rows.Add(parts.Length == 1 ? slowest : slowest with { Name = $"{parts[0]}, {parts[1]}" });
        }

        return rows.ToImmutable();
    }

    private static void Change(PlcMemory memory, IEnumerable<ReadItem> items)
    {
        foreach (var item in items)
        {
            memory.V[item.Offset] ^= 0xFF;
        }
    }
}

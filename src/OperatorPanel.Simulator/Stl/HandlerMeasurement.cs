using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Measures a handler by running it: loads the .awl text in the interpreter, serves the worst-case request of each
/// kind (docs/protocol.md Limits: the largest READ reply, the most items, the longest WRITE, a full list) and counts
/// what its interrupt routines and its slices in OP_PANEL execute, at the StlTiming figures (manual where published, conservative elsewhere).
/// </summary>
public static class HandlerMeasurement
{
    /// <summary>A 119-byte V range the requests read and write; the caller keeps it clear of the handler's bytes.</summary>
    public const int DataBytes = 119;

    /// <summary>The first entry: the handler's scans without a request (its Instructions: the most in one scan).</summary>
    public const string IdleName = "no request (a scan)";

    /// <summary>
    /// Serves the worst-case requests to the handler in <paramref name="awlText"/> on <paramref name="port"/> at
    /// <paramref name="station"/>; <paramref name="dataStart"/> is the first of <see cref="DataBytes"/> free V bytes.
    /// False with the loader's diagnostics when the text does not load.
    /// </summary>
    public static bool TryMeasure(string awlText, CpuProfile cpu, int port, Station station, LineSettings line, int dataStart, out ImmutableArray<MeasuredRequest> requests, out string error)
    {
        ArgumentNullException.ThrowIfNull(cpu);
        var load = StlProgramLoader.Load(awlText, cpu);
        if (load.Program is null)
        {
            (requests, error) = ([], string.Join("; ", load.Diagnostics));
            return false;
        }

        var plc = new StlPlc(load.Program);
        var freeport = new FreeportPort(port, plc.Memory, cpu, line);
        plc.AttachPort(freeport);
        var session = new MeasurementSession(plc, freeport, line, port);
        var builder = ImmutableArray.CreateBuilder<MeasuredRequest>();
        builder.Add(session.Idle(IdleName));
        foreach (var (name, frame) in WorstCases(station, dataStart))
        {
            builder.Add(session.Serve(name, frame));
        }

        (requests, error) = (builder.ToImmutable(), plc.Fault is { } fault ? $"the handler faulted: {fault}" : "");
        return plc.Fault is null;
    }

    private static IEnumerable<(string Name, byte[] Frame)> WorstCases(Station station, int v)
    {
        // 20 items, one every 5 bytes: as much data as a READ of 20 items may reply, and as a list of 20 items may hold
        // (its longest reply, READ CHANGES whole, must end before its descriptors).
        var items = ProtocolLimits.MaxReadItems;
        var twenty = Items(v, items, ProtocolLimits.MaxReadDataFor(items));
        var list = Items(v, items, (ProtocolLimits.MaxFrameChars - (4 * items) - ProtocolLimits.ListReplyChars(0)) / 2);
        yield return ("IDENTIFY", RequestCodec.Encode(new IdentifyRequest(station, 1)));
        yield return ($"READ 1 item {ProtocolLimits.MaxReadData} bytes", RequestCodec.Encode(new ReadRequest(station, 2, [new ReadItem(ProtocolArea.V, v, ProtocolLimits.MaxReadData)])));
        yield return ($"READ 20 items {twenty.Sum(i => i.Length)} bytes", RequestCodec.Encode(new ReadRequest(station, 3, twenty)));
        yield return ($"WRITE {ProtocolLimits.MaxWriteData} bytes", RequestCodec.Encode(new WriteBlockRequest(station, 4, ProtocolArea.V, v, [.. Enumerable.Range(0, ProtocolLimits.MaxWriteData).Select(i => (byte)i)])));
        yield return ("WRITE BIT", RequestCodec.Encode(new WriteBitRequest(station, 5, ProtocolArea.V, v, 3, true)));
        yield return ("DEFINE LIST 20 items", RequestCodec.Encode(new DefineListRequest(station, 6, 1, list)));
        yield return ("READ LIST 20 items", RequestCodec.Encode(new ReadListRequest(station, 7, 1)));

        // READ CHANGES of that list: the first fills the copy (whole list), then none changed (the idle station's
        // cost), one changed, and 40 changed: 2K >= D, compared to the end and then answered whole.
        yield return ($"READ CHANGES {list.Sum(i => i.Length)} bytes whole", RequestCodec.Encode(new ReadChangesRequest(station, 9, 1, false)));
        yield return ("READ CHANGES none changed", RequestCodec.Encode(new ReadChangesRequest(station, 10, 1, false)));
        yield return ("WRITE BIT in the list", RequestCodec.Encode(new WriteBitRequest(station, 11, ProtocolArea.V, v + 80, 0, true)));
        yield return ("READ CHANGES 1 changed", RequestCodec.Encode(new ReadChangesRequest(station, 12, 1, false)));
        yield return ("WRITE 50 bytes in the list", RequestCodec.Encode(new WriteBlockRequest(station, 13, ProtocolArea.V, v, [.. Enumerable.Range(0, 50).Select(i => (byte)~i)])));
        yield return ("READ CHANGES 40 changed", RequestCodec.Encode(new ReadChangesRequest(station, 14, 1, false)));
        var bad = RequestCodec.Encode(new IdentifyRequest(station, 8));
        bad[^2] = (byte)(bad[^2] == '0' ? '1' : '0');
        yield return ("bad block check", bad);
    }

    /// <summary><paramref name="count"/> V items one every 5 bytes from <paramref name="v"/>: 4 bytes each, the last the rest of <paramref name="total"/>.</summary>
    private static ImmutableArray<ReadItem> Items(int v, int count, int total) =>
        [.. Enumerable.Range(0, count).Select(i => new ReadItem(ProtocolArea.V, v + (i * 5), i == count - 1 ? total - (4 * (count - 1)) : 4))];
}

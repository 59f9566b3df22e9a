using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Measures a handler by running it: loads the .awl text in the interpreter, serves the worst-case request of each
/// kind (docs/protocol-v2.md Limits: the largest READ reply, the most items, the longest WRITE, a full list) and counts
/// what its interrupt routines and its slices in OP_PANEL execute, at the StlTiming figures (manual where published, conservative elsewhere).
/// </summary>
public static class HandlerMeasurement
{
    /// <summary>A V range the requests read and write, as long as the longest WRITE; the caller keeps it clear of the handler's bytes.</summary>
    public const int DataBytes = ProtocolLimits.MaxWriteData;

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
        foreach (var (name, frame) in WorstCases(station, dataStart).Concat(ChangesOfLists(station, dataStart)))
        {
            var served = session.Serve(name ?? "", frame);
            if (name is not null)
            {
                builder.Add(served);
            }
        }

        (requests, error) = (builder.ToImmutable(), plc.Fault is { } fault ? $"the handler faulted: {fault}" : "");
        return plc.Fault is null;
    }

    private static IEnumerable<(string? Name, byte[] Frame)> WorstCases(Station station, int v)
    {
        // 19 items of 4 bytes and one of 1: 77 bytes, the most a list of 20 items may have (ListsFit: 80 + 20 + 2 x 77 <= 255).
        ImmutableArray<ReadItem> twenty = [.. Enumerable.Range(0, 20).Select(i => new ReadItem(ProtocolArea.V, v + (i * 5), i == 19 ? 1 : 4))];
        var readTwenty = RequestCodec.Encode(new ReadRequest(station, 3, twenty));
        yield return ("IDENTIFY", RequestCodec.Encode(new IdentifyRequest(station, 1)));
        yield return ($"READ 1 item {ProtocolLimits.MaxReadData} bytes", RequestCodec.Encode(new ReadRequest(station, 2, [new ReadItem(ProtocolArea.V, v, ProtocolLimits.MaxReadData)])));
        yield return ("READ 20 items 77 bytes", readTwenty);
        yield return ($"WRITE {DataBytes} bytes", RequestCodec.Encode(new WriteBlockRequest(station, 4, ProtocolArea.V, v, [.. Enumerable.Range(0, DataBytes).Select(i => (byte)i)])));
        yield return ("WRITE BIT", RequestCodec.Encode(new WriteBitRequest(station, 5, ProtocolArea.V, v, 3, true)));
        yield return ("DEFINE LIST 20 items", RequestCodec.Encode(new DefineListRequest(station, 6, 1, twenty)));
        yield return ("READ LIST 20 items", RequestCodec.Encode(new ReadListRequest(station, 7, 1)));

        // READ CHANGES of that list: the first fills the copy (whole list), then none changed (the idle station's
        // cost), one changed, and 40 changed: 2K >= D, compared to the end and then answered whole.
        yield return ("READ CHANGES 77 bytes whole", RequestCodec.Encode(new ReadChangesRequest(station, 9, 1, false)));
        yield return ("READ CHANGES none changed", RequestCodec.Encode(new ReadChangesRequest(station, 10, 1, false)));
        yield return ("WRITE BIT in the list", RequestCodec.Encode(new WriteBitRequest(station, 11, ProtocolArea.V, v + 80, 0, true)));
        yield return ("READ CHANGES 1 changed", RequestCodec.Encode(new ReadChangesRequest(station, 12, 1, false)));
        yield return ("WRITE 50 bytes in the list", RequestCodec.Encode(new WriteBlockRequest(station, 13, ProtocolArea.V, v, [.. Enumerable.Range(0, 50).Select(i => (byte)~i)])));
        yield return ("READ CHANGES 40 changed", RequestCodec.Encode(new ReadChangesRequest(station, 14, 1, false)));
        var bad = RequestCodec.Encode(new IdentifyRequest(station, 8));
        bad[^2] ^= 0x01;
        yield return ("bad frame check", bad);

        // The frame after the remains of a cut-off one: checked from the last '<' and moved down to buffer byte 1.
        yield return ("cut-off frame, then READ 20 items", [.. readTwenty.AsSpan(0, 60), .. readTwenty]);
        var other = new Station(station.Address % 126 + 1);
        yield return ("READ 20 items for another station", RequestCodec.Encode(new ReadRequest(other, 9, twenty)));
    }

    /// <summary>
    /// 09 READ CHANGES OF LISTS, after the requests that prepare it (no name: served, not reported). Two lists of the
    /// reference line's size (20 items and 13, 37 bytes each) idle, beside the two READ CHANGES it replaces; then four
    /// lists of 10 two-byte items: first without a valid copy (four REREAD entries in the scan that decodes the request),
    /// then with 9 bytes changed in each: the first list's pairs fit, the other three's do not (REREAD after a whole
    /// comparison, the pairs written up to the room left).
    /// </summary>
    private static IEnumerable<(string? Name, byte[] Frame)> ChangesOfLists(Station station, int v)
    {
        byte sequence = 20;
        ImmutableArray<ReadItem> first = [.. Enumerable.Range(0, 20).Select(i => new ReadItem(ProtocolArea.V, v + (i * 5), i < 17 ? 2 : 1))];
        ImmutableArray<ReadItem> second = [.. Enumerable.Range(0, 13).Select(i => new ReadItem(ProtocolArea.V, v + (i * 8), i < 11 ? 3 : 2))];
        yield return (null, RequestCodec.Encode(new DefineListRequest(station, sequence++, 1, first)));
        yield return (null, RequestCodec.Encode(new DefineListRequest(station, sequence++, 2, second)));
        yield return (null, RequestCodec.Encode(new ReadChangesRequest(station, sequence++, 1, true)));
        yield return (null, RequestCodec.Encode(new ReadChangesRequest(station, sequence++, 2, true)));
        yield return ("READ CHANGES list 1 of 2, none changed", RequestCodec.Encode(new ReadChangesRequest(station, sequence++, 1, false)));
        yield return ("READ CHANGES list 2 of 2, none changed", RequestCodec.Encode(new ReadChangesRequest(station, sequence++, 2, false)));
        yield return ("READ CHANGES OF LISTS 2 lists idle", ChangesOfListsFrame(station, sequence++, 0b0011));

        const int lists = 4, items = 10, itemBytes = 2, listBytes = items * itemBytes;
        yield return (null, RequestCodec.Encode(new WriteBlockRequest(station, sequence++, ProtocolArea.V, v, [.. new byte[lists * listBytes]])));
        for (var list = 1; list <= lists; list++)
        {
            var at = v + ((list - 1) * listBytes);
            yield return (null, RequestCodec.Encode(new DefineListRequest(station, sequence++, list, [.. Enumerable.Range(0, items).Select(i => new ReadItem(ProtocolArea.V, at + (i * itemBytes), itemBytes))])));
        }

        yield return ("READ CHANGES OF LISTS 4 lists, no valid copy", ChangesOfListsFrame(station, sequence++, 0b1111));
        for (var list = 1; list <= lists; list++)
        {
            yield return (null, RequestCodec.Encode(new ReadChangesRequest(station, sequence++, list, true)));
        }

        for (var list = 1; list <= lists; list++)
        {
            var changed = Enumerable.Range(0, listBytes).Select(b => (byte)(b % itemBytes == 0 && b / itemBytes < 9 ? 0xA5 : 0)).ToArray();
            yield return (null, RequestCodec.Encode(new WriteBlockRequest(station, sequence++, ProtocolArea.V, v + ((list - 1) * listBytes), [.. changed])));
        }

        yield return ("READ CHANGES OF LISTS 4 lists, 9 changed in each", ChangesOfListsFrame(station, sequence, 0b1111));
    }

    private static byte[] ChangesOfListsFrame(Station station, byte sequence, byte mask) =>
        RequestCodec.Encode(new ReadChangesOfListsRequest(station, sequence, mask));
}

using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Replies on the wire: STATION SEQ CMD|16#80 STATUS REQCHECK PAYLOAD (docs/protocol-v2.md, "Commands" and "Error
/// replies"). A station encodes them; the panel decodes one against the request it sent, REQCHECK included.
/// </summary>
public static class ResponseCodec
{
    /// <summary>IDENTIFY reply payload after STATUS and REQCHECK: v1's 15 bytes, PORT, V_FIRST, V_BYTES, FEATURES, COPY_BYTES.</summary>
    public const int IdentifyPayloadBytes = 22;

    /// <summary>Encodes <paramref name="response"/> with the REQCHECK it carries (<see cref="PlcResponse.RequestCheck"/>).</summary>
    public static byte[] Encode(PlcResponse response) => FrameCodec.Encode(ToFrame(response));

    /// <summary>Encodes <paramref name="response"/> as the reply to <paramref name="answering"/> (REQCHECK = its check).</summary>
    public static byte[] Encode(PlcResponse response, PlcRequest answering)
    {
        ArgumentNullException.ThrowIfNull(response);
        return Encode(response with { RequestCheck = RequestCodec.Check(answering) });
    }

    public static FreeportFrame ToFrame(PlcResponse response)
    {
        ArgumentNullException.ThrowIfNull(response);
        ImmutableArray<byte> payload = response switch
        {
            ErrorResponse error when error.Error != ProtocolError.None => [],
            ErrorResponse => throw new ArgumentException("an error reply needs a non-zero status", nameof(response)),
            IdentifyResponse identify => IdentifyPayload(identify),
            ReadResponse read => read.Data,
            WriteBlockResponse write => write.ReadBack,
            WriteBitResponse bit => [bit.ReadBack],
            DefineListResponse => [],
            ReadListResponse list => list.Data,
            StopResponse => [],
            ReadChangesResponse changes => ChangesPayload(changes),
            ReadChangesOfListsResponse lists => [.. lists.Lists.SelectMany(ListPayload)],
            _ => throw new ArgumentException($"unknown response type {response.GetType().Name}", nameof(response)),
        };
        var status = response is ErrorResponse e ? (byte)e.Error : (byte)0;
        var command = (byte)((byte)response.Command | FreeportFrame.ReplyBit);
        return new FreeportFrame(
            (byte)response.Station.Address, response.Sequence, command, [status, (byte)(response.RequestCheck >> 8), (byte)response.RequestCheck, .. payload]);
    }

    /// <summary>Decodes the frame characters and checks that they answer <paramref name="request"/> as encoded.</summary>
    public static bool TryDecode(ReadOnlySpan<byte> frameChars, PlcRequest request, out PlcResponse response, out FrameError error) =>
        TryDecode(frameChars, request, RequestCodec.Check(request), out response, out error);

    /// <summary>
    /// Decodes the frame characters and checks that they answer <paramref name="request"/>, sent with check
    /// <paramref name="requestCheck"/>: <see cref="FrameError.RequestCheckMismatch"/> when STATION, SEQ and CMD match but
    /// REQCHECK does not (the PLC acted on a corrupted copy; <paramref name="response"/> is then null).
    /// </summary>
    public static bool TryDecode(ReadOnlySpan<byte> frameChars, PlcRequest request, ushort requestCheck, out PlcResponse response, out FrameError error)
    {
        response = null!;
        return FrameCodec.TryDecode(frameChars, out var frame, out error) && TryDecode(frame, request, requestCheck, out response, out error);
    }

    public static bool TryDecode(FreeportFrame frame, PlcRequest request, ushort requestCheck, out PlcResponse response, out FrameError error)
    {
        ArgumentNullException.ThrowIfNull(frame);
        ArgumentNullException.ThrowIfNull(request);
        response = null!;
        error = CheckHeader(frame, request, requestCheck);
        if (error != FrameError.None)
        {
            return false;
        }

        var status = frame.Payload[0];
        var data = frame.Payload.AsSpan()[3..];
        if (status != 0)
        {
            error = status is < (byte)ProtocolError.AddressOutOfRange or > (byte)ProtocolError.ListNotDefined ? FrameError.UnknownStatus
                : data.Length != 0 ? FrameError.LengthMismatch
                : FrameError.None;
            response = new ErrorResponse(request.Station, request.Sequence, request.Command, (ProtocolError)status) { RequestCheck = requestCheck };
            return error == FrameError.None;
        }

        if (!LengthFits(request, data))
        {
            error = FrameError.LengthMismatch;
            return false;
        }

        // By command code, not by request type: a new command fails the build here until its reply is decoded.
        PlcResponse decoded = request.Command switch
        {
            CommandCode.Identify => Identify(request, data),
            CommandCode.Read => new ReadResponse(request.Station, request.Sequence, [.. data]),
            CommandCode.Write => new WriteBlockResponse(request.Station, request.Sequence, [.. data]),
            CommandCode.WriteBit => new WriteBitResponse(request.Station, request.Sequence, data[0]),
            CommandCode.DefineList => new DefineListResponse(request.Station, request.Sequence),
            CommandCode.ReadList => new ReadListResponse(request.Station, request.Sequence, [.. data]),
            CommandCode.Stop => new StopResponse(request.Station, request.Sequence),
            CommandCode.ReadChanges => Changes(request, data),
            CommandCode.ReadChangesOfLists => ChangesOfLists(request, data),
        };
        response = decoded with { RequestCheck = requestCheck };
        return true;
    }

    /// <summary>
    /// Data bytes a successful reply to <paramref name="request"/> carries after STATUS and REQCHECK; for READ LIST and
    /// READ CHANGES, whose length only the stored list knows, the most a reply can carry.
    /// </summary>
    public static int ExpectedDataBytes(PlcRequest request) => request switch
    {
        IdentifyRequest => IdentifyPayloadBytes,
        ReadRequest read => read.TotalLength,
        WriteBlockRequest write => write.Data.Length,
        WriteBitRequest => 1,
        DefineListRequest => 0,
        ReadListRequest => ProtocolLimits.MaxReadData,
        StopRequest => 0,
        ReadChangesRequest => 1 + ProtocolLimits.MaxReadData,
        ReadChangesOfListsRequest => ProtocolLimits.MaxReplyPayload,
        _ => throw new ArgumentException($"unknown request type {request.GetType().Name}", nameof(request)),
    };

    private static FrameError CheckHeader(FreeportFrame frame, PlcRequest request, ushort requestCheck) =>
        !frame.IsReply ? FrameError.NotAReply
        : frame.Station != request.Station.Address ? FrameError.StationMismatch
        : frame.Sequence != request.Sequence ? FrameError.SequenceMismatch
        : (frame.Command & ~FreeportFrame.ReplyBit) != (byte)request.Command ? FrameError.CommandMismatch
        : frame.Payload.Length < ProtocolLimits.ReplyHeaderBytes - FreeportFrame.OverheadBytes ? FrameError.LengthMismatch
        : ((frame.Payload[1] << 8) | frame.Payload[2]) != requestCheck ? FrameError.RequestCheckMismatch
        : FrameError.None;

    /// <summary>
    /// A READ LIST reply: any READ-sized data (the caller checks it against its list). A READ CHANGES reply: K = 16#FF
    /// and 1 .. MAX_READ_DATA bytes, or K = 0-127 and exactly K pairs with strictly ascending indexes.
    /// </summary>
    private static bool LengthFits(PlcRequest request, ReadOnlySpan<byte> data) => request switch
    {
        ReadListRequest => data.Length <= ProtocolLimits.MaxReadData,
        ReadChangesRequest => data.Length >= 1 && (data[0] == ProtocolLimits.FullListMarker
            ? data.Length - 1 is >= 1 and <= ProtocolLimits.MaxReadData
            : data[0] <= 127 && data.Length == 1 + (2 * data[0]) && Ascending(data[1..])),
        ReadChangesOfListsRequest lists => EntriesFit(data, lists.Lists.Count),
        _ => data.Length == ExpectedDataBytes(request),
    };

    /// <summary>
    /// Exactly <paramref name="entries"/> entries fill the data: each K = 16#FE alone, or K = 0-127 and K pairs with
    /// strictly ascending indexes.
    /// </summary>
    private static bool EntriesFit(ReadOnlySpan<byte> data, int entries)
    {
        var at = 0;
        for (var entry = 0; entry < entries; entry++)
        {
            if (at >= data.Length)
            {
                return false;
            }

            var k = data[at];
            if (k == ProtocolLimits.RereadListMarker)
            {
                at++;
                continue;
            }

            var end = at + 1 + (2 * k);
            if (k > 127 || end > data.Length || !Ascending(data[(at + 1)..end]))
            {
                return false;
            }

            at = end;
        }

        return at == data.Length;
    }

    private static bool Ascending(ReadOnlySpan<byte> pairs)
    {
        for (var i = 2; i < pairs.Length; i += 2)
        {
            if (pairs[i] <= pairs[i - 2])
            {
                return false;
            }
        }

        return true;
    }

    private static ImmutableArray<byte> ChangesPayload(ReadChangesResponse r) => r.Full
        ? [ProtocolLimits.FullListMarker, .. r.Data]
        : [(byte)r.Changes.Length, .. r.Changes.SelectMany(c => new[] { c.Index, c.Value })];

    private static ReadChangesResponse Changes(PlcRequest request, ReadOnlySpan<byte> d)
    {
        if (d[0] == ProtocolLimits.FullListMarker)
        {
            return ReadChangesResponse.Whole(request.Station, request.Sequence, [.. d[1..]]);
        }

        var changes = ImmutableArray.CreateBuilder<ChangedByte>(d[0]);
        for (var at = 1; at < d.Length; at += 2)
        {
            changes.Add(new ChangedByte(d[at], d[at + 1]));
        }

        return ReadChangesResponse.Pairs(request.Station, request.Sequence, changes.MoveToImmutable());
    }

    private static IEnumerable<byte> ListPayload(ListChanges entry) => entry.Reread
        ? [ProtocolLimits.RereadListMarker]
        : [(byte)entry.Changes.Length, .. entry.Changes.SelectMany(c => new[] { c.Index, c.Value })];

    /// <summary>The entries, one per list of the mask in ascending id; <see cref="EntriesFit"/> has checked their shape.</summary>
    private static ReadChangesOfListsResponse ChangesOfLists(PlcRequest request, ReadOnlySpan<byte> d)
    {
        var lists = ((ReadChangesOfListsRequest)request).Lists;
        var entries = ImmutableArray.CreateBuilder<ListChanges>(lists.Count);
        var at = 0;
        foreach (var list in lists)
        {
            var k = d[at++];
            if (k == ProtocolLimits.RereadListMarker)
            {
                entries.Add(ListChanges.RereadList(list));
                continue;
            }

            var changes = ImmutableArray.CreateBuilder<ChangedByte>(k);
            for (var pair = 0; pair < k; pair++, at += 2)
            {
                changes.Add(new ChangedByte(d[at], d[at + 1]));
            }

            entries.Add(ListChanges.Pairs(list, changes.MoveToImmutable()));
        }

        return new ReadChangesOfListsResponse(request.Station, request.Sequence, entries.MoveToImmutable());
    }

    private static ImmutableArray<byte> IdentifyPayload(IdentifyResponse r) =>
    [
        r.ProtocolVersion, r.HandlerRevision, r.CpuModelCode, r.CpuRevisionCode, r.WriteMask, r.MaxReadData,
        r.ReplyDelayMs, r.Smb6, r.StatusFlags,
        (byte)(r.LastScanMs >> 8), (byte)r.LastScanMs,
        (byte)(r.MinScanMs >> 8), (byte)r.MinScanMs,
        (byte)(r.MaxScanMs >> 8), (byte)r.MaxScanMs,
        r.Port, (byte)(r.VFirst >> 8), (byte)r.VFirst, (byte)(r.VBytes >> 8), (byte)r.VBytes, r.Features, r.CopyBytes,
    ];

    private static IdentifyResponse Identify(PlcRequest request, ReadOnlySpan<byte> d) =>
        new(request.Station, request.Sequence, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8],
            Word(d, 9), Word(d, 11), Word(d, 13), d[15], Word(d, 16), Word(d, 18), d[20], d[21]);

    private static ushort Word(ReadOnlySpan<byte> d, int at) => (ushort)((d[at] << 8) | d[at + 1]);
}

using System.Collections.Immutable;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// Replies on the wire: STATION SEQ CMD|16#80 STATUS PAYLOAD (docs/protocol.md, "Commands" and "Error replies").
/// A station encodes them; the panel decodes one against the request it sent.
/// </summary>
public static class ResponseCodec
{
    /// <summary>IDENTIFY reply payload after STATUS: 9 single bytes and 3 scan-time words.</summary>
    public const int IdentifyPayloadBytes = 15;

    public static byte[] Encode(PlcResponse response) => FrameCodec.Encode(ToFrame(response));

    public static FreeportFrame ToFrame(PlcResponse response)
    {
        ArgumentNullException.ThrowIfNull(response);
        ImmutableArray<byte> payload = response switch
        {
            ErrorResponse error when error.Error != ProtocolError.None => [(byte)error.Error],
            ErrorResponse => throw new ArgumentException("an error reply needs a non-zero status", nameof(response)),
            IdentifyResponse identify => [0, .. IdentifyPayload(identify)],
            ReadResponse read => [0, .. read.Data],
            WriteBlockResponse write => [0, .. write.ReadBack],
            WriteBitResponse bit => [0, bit.ReadBack],
            DefineListResponse => [0],
            ReadListResponse list => [0, .. list.Data],
            _ => throw new ArgumentException($"unknown response type {response.GetType().Name}", nameof(response)),
        };
        var command = (byte)((byte)response.Command | FreeportFrame.ReplyBit);
        return new FreeportFrame((byte)response.Station.Address, response.Sequence, command, payload);
    }

    /// <summary>Decodes the frame characters and checks that they answer <paramref name="request"/>.</summary>
    public static bool TryDecode(ReadOnlySpan<byte> frameChars, PlcRequest request, out PlcResponse response, out FrameError error)
    {
        response = null!;
        return FrameCodec.TryDecode(frameChars, out var frame, out error) && TryDecode(frame, request, out response, out error);
    }

    public static bool TryDecode(FreeportFrame frame, PlcRequest request, out PlcResponse response, out FrameError error)
    {
        ArgumentNullException.ThrowIfNull(frame);
        ArgumentNullException.ThrowIfNull(request);
        response = null!;
        error = CheckHeader(frame, request);
        if (error != FrameError.None)
        {
            return false;
        }

        var status = frame.Payload[0];
        var data = frame.Payload.AsSpan()[1..];
        if (status != 0)
        {
            error = status is < (byte)ProtocolError.AddressOutOfRange or > (byte)ProtocolError.ListNotDefined ? FrameError.UnknownStatus
                : data.Length != 0 ? FrameError.LengthMismatch
                : FrameError.None;
            response = new ErrorResponse(request.Station, request.Sequence, request.Command, (ProtocolError)status);
            return error == FrameError.None;
        }

        // A READ LIST request does not say how long its list is: any READ-sized reply is taken; the caller checks it.
        if (request is ReadListRequest ? data.Length > ProtocolLimits.MaxReadData : data.Length != ExpectedDataBytes(request))
        {
            error = FrameError.LengthMismatch;
            return false;
        }

        // By command code, not by request type: a new command fails the build here until its reply is decoded.
        response = request.Command switch
        {
            CommandCode.Identify => Identify(request, data),
            CommandCode.Read => new ReadResponse(request.Station, request.Sequence, [.. data]),
            CommandCode.Write => new WriteBlockResponse(request.Station, request.Sequence, [.. data]),
            CommandCode.WriteBit => new WriteBitResponse(request.Station, request.Sequence, data[0]),
            CommandCode.DefineList => new DefineListResponse(request.Station, request.Sequence),
            CommandCode.ReadList => new ReadListResponse(request.Station, request.Sequence, [.. data]),
        };
        return true;
    }

    private static FrameError CheckHeader(FreeportFrame frame, PlcRequest request) =>
        !frame.IsReply ? FrameError.NotAReply
        : frame.Station != request.Station.Address ? FrameError.StationMismatch
        : frame.Sequence != request.Sequence ? FrameError.SequenceMismatch
        : (frame.Command & ~FreeportFrame.ReplyBit) != (byte)request.Command ? FrameError.CommandMismatch
        : frame.Payload.IsEmpty ? FrameError.LengthMismatch
        : FrameError.None;

    /// <summary>
    /// Data bytes a successful reply to <paramref name="request"/> carries after STATUS; for READ LIST, whose length only
    /// the stored list knows, the most a reply can carry (<see cref="ProtocolLimits.MaxReadData"/>).
    /// </summary>
    public static int ExpectedDataBytes(PlcRequest request) => request switch
    {
        IdentifyRequest => IdentifyPayloadBytes,
        ReadRequest read => read.TotalLength,
        WriteBlockRequest write => write.Data.Length,
        WriteBitRequest => 1,
        DefineListRequest => 0,
        ReadListRequest => ProtocolLimits.MaxReadData,
        _ => throw new ArgumentException($"unknown request type {request.GetType().Name}", nameof(request)),
    };

    private static byte[] IdentifyPayload(IdentifyResponse r) =>
    [
        r.ProtocolVersion, r.HandlerRevision, r.CpuModelCode, r.CpuRevisionCode, r.WriteMask, r.MaxReadData,
        r.ReplyDelayMs, r.Smb6, r.StatusFlags,
        (byte)(r.LastScanMs >> 8), (byte)r.LastScanMs,
        (byte)(r.MinScanMs >> 8), (byte)r.MinScanMs,
        (byte)(r.MaxScanMs >> 8), (byte)r.MaxScanMs,
    ];

    private static IdentifyResponse Identify(PlcRequest request, ReadOnlySpan<byte> d) =>
        new(request.Station, request.Sequence, d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8],
            (ushort)((d[9] << 8) | d[10]), (ushort)((d[11] << 8) | d[12]), (ushort)((d[13] << 8) | d[14]));
}

using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Timing and retry rules of a <see cref="PlcLink"/>. The reply timeout follows docs/protocol.md, "Timing": request
/// time + reply delay + scan allowance + the handler's scans (<see cref="HandlerTurnaround"/>) x handler scan allowance
/// + reply time + what the medium adds (<see cref="RadioModuleProfile"/>) + margin.
/// </summary>
public sealed record LinkOptions
{
    /// <summary>Options for a bus with the medium's own retries and inter-frame gap (cable or radio module).</summary>
    public static LinkOptions For(SerialSettings serial, byte replyDelayMs = 5)
    {
        ArgumentNullException.ThrowIfNull(serial);
        var medium = RadioModuleProfile.For(serial.Kind);
        return new LinkOptions
        {
            Serial = serial,
            Medium = medium,
            Retries = medium.Retries,
            InterFrameGap = medium.InterFrameGap,
            ReplyDelay = TimeSpan.FromMilliseconds(replyDelayMs),
        };
    }

    public required SerialSettings Serial { get; init; }

    /// <summary>What the way to the bus adds to each exchange; the cable adds nothing.</summary>
    public RadioModuleProfile Medium { get; init; } = RadioModuleProfile.Cable;

    /// <summary>Further attempts after the first; the identical frame is resent (writes are idempotent).</summary>
    public int Retries { get; init; } = 2;

    /// <summary>The reply delay the handler was generated with (timed interrupt, 1-255 ms; seed 004 uses 5 ms).</summary>
    public TimeSpan ReplyDelay { get; init; } = TimeSpan.FromMilliseconds(5);

    /// <summary>Longest time the PLC may take before it starts serving the request (up to one scan).</summary>
    public TimeSpan ScanAllowance { get; init; } = TimeSpan.FromMilliseconds(100);

    /// <summary>
    /// Time allowed for each scan the handler takes to serve a request: the user's program plus the handler's slice
    /// of at most 10 ms. 30 ms covers programs scanning in up to 20 ms (most lines; IDENTIFY reports SMW22-26).
    /// </summary>
    public TimeSpan HandlerScanAllowance { get; init; } = TimeSpan.FromMilliseconds(30);

    /// <summary>Quiet time on the line between the end of one exchange and the next request.</summary>
    public TimeSpan InterFrameGap { get; init; } = TimeSpan.Zero;

    /// <summary>Slack for OS and converter buffering.</summary>
    public TimeSpan Margin { get; init; } = TimeSpan.FromMilliseconds(20);

    public TimeSpan ReplyTimeoutFor(PlcRequest request) => ReplyTimeoutFor(request, RequestCodec.Encode(request).Length);

    /// <summary>The reply timeout when the request's frame is already encoded (<paramref name="requestChars"/> long).</summary>
    public TimeSpan ReplyTimeoutFor(PlcRequest request, int requestChars)
    {
        ArgumentNullException.ThrowIfNull(request);
        var replyChars = ProtocolLimits.ReplyChars(ResponseCodec.ExpectedDataBytes(request));
        return (Serial.CharacterTime * (requestChars + replyChars))
            + ReplyDelay + ScanAllowance + (HandlerScanAllowance * HandlerTurnaround.ScansFor(requestChars, replyChars))
            + Medium.ExtraFor(Serial, requestChars, replyChars) + Margin;
    }
}

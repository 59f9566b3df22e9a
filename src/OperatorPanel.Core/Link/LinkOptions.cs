using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Timing and retry rules of a <see cref="PlcLink"/>. The reply timeout follows docs/protocol.md, "Timing":
/// request time + reply delay + scan allowance + reply time + extra latency + margin.
/// </summary>
public sealed record LinkOptions
{
    public required SerialSettings Serial { get; init; }

    /// <summary>Further attempts after the first; the identical frame is resent (writes are idempotent).</summary>
    public int Retries { get; init; } = 2;

    /// <summary>The reply delay the handler was generated with (timed interrupt, 1-255 ms; seed 004 uses 5 ms).</summary>
    public TimeSpan ReplyDelay { get; init; } = TimeSpan.FromMilliseconds(5);

    /// <summary>Longest time the PLC may take before it starts serving the request (up to one scan).</summary>
    public TimeSpan ScanAllowance { get; init; } = TimeSpan.FromMilliseconds(100);

    /// <summary>Added latency of the medium, e.g. the radio modules' store-and-forward.</summary>
    public TimeSpan ExtraLatency { get; init; } = TimeSpan.Zero;

    /// <summary>Quiet time on the line between the end of one exchange and the next request.</summary>
    public TimeSpan InterFrameGap { get; init; } = TimeSpan.Zero;

    /// <summary>Slack for OS and converter buffering.</summary>
    public TimeSpan Margin { get; init; } = TimeSpan.FromMilliseconds(20);

    public TimeSpan ReplyTimeoutFor(PlcRequest request)
    {
        ArgumentNullException.ThrowIfNull(request);
        var requestChars = RequestCodec.Encode(request).Length;
        var replyChars = 2 + (2 * (FreeportFrame.OverheadBytes + 1 + ResponseCodec.ExpectedDataBytes(request)));
        return (Serial.CharacterTime * (requestChars + replyChars)) + ReplyDelay + ScanAllowance + ExtraLatency + Margin;
    }
}

using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Link;

/// <summary>
/// Timing and retry rules of a <see cref="PlcLink"/>. The reply timeout follows docs/protocol-v2.md, "Timing": request
/// time + reply delay + scan allowance + the handler's scans (<see cref="HandlerTurnaround"/>) x handler scan allowance
/// + reply time + what the medium adds (<see cref="RadioModuleProfile"/>) + margin.
/// </summary>
public sealed record LinkOptions
{
    /// <summary>The floor of the protocol's minimum gap (docs/protocol-v2.md, "Minimum gap").</summary>
    public static readonly TimeSpan MinimumGapFloor = TimeSpan.FromMilliseconds(5);

    /// <summary>The minimum gap in character times at the bus baud rate (docs/protocol-v2.md, "Minimum gap").</summary>
    public const int MinimumGapCharacters = 3;

    /// <summary>
    /// Options for a bus with the medium's own retries, and as gap the longer of the protocol's minimum gap and the
    /// medium's own (the radio module's 20 ms).
    /// </summary>
    public static LinkOptions For(SerialSettings serial, byte replyDelayMs = 5)
    {
        ArgumentNullException.ThrowIfNull(serial);
        var medium = RadioModuleProfile.For(serial.Kind);
        var options = new LinkOptions
        {
            Serial = serial,
            Medium = medium,
            Retries = medium.Retries,
            ReplyDelay = TimeSpan.FromMilliseconds(replyDelayMs),
        };
        return options with { InterFrameGap = options.MinimumGap > medium.InterFrameGap ? options.MinimumGap : medium.InterFrameGap };
    }

    public required SerialSettings Serial { get; init; }

    /// <summary>What the way to the bus adds to each exchange; the cable adds nothing.</summary>
    public RadioModuleProfile Medium { get; init; } = RadioModuleProfile.Cable;

    /// <summary>
    /// Further attempts after the first, of the identical frame; never for a request that acts on the process
    /// (<see cref="PlcLink.ActsOnProcess"/>), which is resolved by reading back instead.
    /// </summary>
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

    /// <summary>
    /// The protocol's minimum gap: after the '&gt;' of any frame on the bus, or a timeout, the PC sends the next '&lt;'
    /// no sooner than 5 ms and 3 character times later (docs/protocol-v2.md, "Minimum gap"). A station's receive interrupt
    /// may be delayed by the user's own interrupt routines; until it re-arms RCV, a start character is lost, and with it
    /// the whole request. 3 character times matter below 6600 baud (1200 baud: 27.5 ms).
    /// </summary>
    public TimeSpan MinimumGap
    {
        get
        {
            var characters = Serial.CharacterTime * MinimumGapCharacters;
            return characters > MinimumGapFloor ? characters : MinimumGapFloor;
        }
    }

    /// <summary>
    /// Quiet time the link keeps between the end of a frame (reply '&gt;' or timeout) and its next request:
    /// <see cref="For"/> sets the longer of <see cref="MinimumGap"/> and the medium's own gap; zero only in tests.
    /// </summary>
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
            + ReplyDelay + ScanAllowance + (HandlerScanAllowance * HandlerTurnaround.ScansFor(request, requestChars))
            + Medium.ExtraFor(Serial, requestChars, replyChars) + Margin;
    }
}

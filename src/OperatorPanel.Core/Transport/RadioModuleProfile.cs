namespace OperatorPanel.Core.Transport;

/// <summary>
/// Timing allowances of the way the PC reaches the bus, on top of the protocol's reply-time budget
/// (docs/protocol-v2.md: timeout = budget + scan allowance + margin; "radio modules add their own latency").
/// <see cref="For"/> gives the cable baseline and the 433 MHz radio module pair of seed 000 §6.
/// </summary>
/// <param name="Kind">The link these numbers are for.</param>
/// <param name="ReplyTimeoutExtra">Fixed latency added to every reply timeout.</param>
/// <param name="ExtraCharacterPasses">
/// How many more times each character crosses a UART at the bus baud rate than on a cable; a store-and-forward hop
/// receives a whole frame before passing it on, so its frames take their line time once more.
/// </param>
/// <param name="Retries">Repeats of a request after its first attempt got no valid reply.</param>
/// <param name="InterFrameGap">Quiet time between a reply's '&gt;' (or a timeout) and the next request.</param>
public sealed record RadioModuleProfile(
    LinkKind Kind,
    TimeSpan ReplyTimeoutExtra,
    int ExtraCharacterPasses,
    int Retries,
    TimeSpan InterFrameGap)
{
    /// <summary>
    /// PC/PPI cable: converts levels bit by bit, so no latency of its own. One retry rides out a single noise burst
    /// (a contactor switching next to the bus) while an unplugged station is reported offline after two timeouts.
    /// 5 ms of gap lets the handler's XMT-complete interrupt re-arm RCV before the next '&lt;' arrives; a start
    /// character that comes before RCV is armed is lost and with it the whole request.
    /// </summary>
    public static RadioModuleProfile Cable { get; } = new(
        LinkKind.Cable,
        ReplyTimeoutExtra: TimeSpan.Zero,
        ExtraCharacterPasses: 0,
        Retries: 1,
        InterFrameGap: TimeSpan.FromMilliseconds(5));

    /// <summary>
    /// The radio pair of seed 000 §6: PC → FT232R (USB) → ATmega16L → CC1100 433 MHz → ATmega16L → MAX232 →
    /// PC/PPI cable → PLC, and back.
    /// Extra 250 ms: the FT232R holds received bytes up to its 16 ms latency timer before sending them to the PC
    /// (FTDI AN232B-04, default setting); each direction is one CC1100 packet exchange whose air time, preamble and
    /// sync word, and TX/RX calibration come to tens of ms for a 255-character frame at the module's radio rate; and
    /// the MCUs forward from an interrupt routine, so a busy MCU delays a packet. 250 ms covers both directions with
    /// room; an operator does not notice it on a panel refreshing a few times a second.
    /// One extra character pass: each module's MCU receives a frame (from '&lt;', seed 000 §6) before the far one sends
    /// it again over its UART, so a frame crosses the bus baud rate twice.
    /// Three retries: the 433 MHz band is shared (remote controls, sensors) and the modules have no link-layer
    /// acknowledgement of their own, so lost packets are normal and the protocol's idempotent commands make a
    /// repeat harmless.
    /// 20 ms gap: longer than the FT232R latency timer, so the tail of a late reply still queued in the FTDI buffer
    /// reaches the PC and is discarded before the next request rather than being taken for its reply.
    /// </summary>
    public static RadioModuleProfile RadioModule { get; } = new(
        LinkKind.RadioModule,
        ReplyTimeoutExtra: TimeSpan.FromMilliseconds(250),
        ExtraCharacterPasses: 1,
        Retries: 3,
        InterFrameGap: TimeSpan.FromMilliseconds(20));

    /// <summary>The profile of a link kind; a value outside the named kinds (a bad cast) is refused by name.</summary>
    public static RadioModuleProfile For(LinkKind kind) => !Enum.IsDefined(kind)
        ? throw new ArgumentOutOfRangeException(nameof(kind), kind, "unknown link kind")
        : kind switch
        {
            LinkKind.Cable => Cable,
            LinkKind.RadioModule => RadioModule,
        };

    /// <summary>
    /// What this link adds to the reply timeout of one exchange: the fixed latency plus the extra line time of the
    /// request and reply frames (<paramref name="requestCharacters"/> and <paramref name="replyCharacters"/>, both
    /// counted with '&lt;' and '&gt;') at <paramref name="settings"/>.
    /// </summary>
    public TimeSpan ExtraFor(SerialSettings settings, int requestCharacters, int replyCharacters)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentOutOfRangeException.ThrowIfNegative(requestCharacters);
        ArgumentOutOfRangeException.ThrowIfNegative(replyCharacters);
        return ReplyTimeoutExtra + (settings.CharacterTime * (ExtraCharacterPasses * (requestCharacters + replyCharacters)));
    }
}

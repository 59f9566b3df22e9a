using System.Globalization;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// Where the handler keeps its bytes in V memory (docs/protocol-v2.md, "Work bytes"): the 256-byte buffer (byte 0 =
/// RCV/XMT count, bytes 1-255 the frame) and the work bytes after it. Pointers live in AC0-AC3 while OP_PANEL works on
/// a request and in SAVE between its scans (a user's program may use the accumulators); nothing in L memory. The
/// order of the work bytes matters: one ATH fills N, I, CMD from the header; one HTA writes CMD|80, STATUS (kept in
/// LIST) and REQCHECK into the reply; START and LCOUNT are indexed by the list id; SAVE holds AC0-AC3 in that order.
/// N, I, CMD and LIST double as <see cref="Scratch"/> while a frame's check is computed (before the request's header
/// is decoded, after the reply's header is written): the CRC's temporary word and the four check characters.
/// </summary>
public sealed partial class HandlerLayout(int bufferStart, int copyBytes)
{
    /// <summary>The work bytes after the buffer: Core's count, which the reference model and IDENTIFY's V_BYTES use too.</summary>
    public const int WorkBytes = HandlerMemory.WorkBytes;

    public const int Subroutines = 1;
    public const int Interrupts = 3;

    /// <summary>Offsets from the buffer start.</summary>
    public const int N = 256, I = 257, Cmd = 258, List = 259, ReqCheck = 260, MaxD = 262, LastFree = 263, Start1 = 264, LCount1 = 268;

    /// <summary>Offsets of the scan-slice state (docs/protocol-v2.md, "Work bytes").</summary>
    public const int Step = 272, Budget = 273, Chunk = 274, Save = 276;

    /// <summary>The CRC register (high byte first, as every S7-200 word) and the sum of the item lengths.</summary>
    public const int Crc = 292, D = 294;

    /// <summary>295 .. the last work byte: kept for 07 STOP and 08 READ CHANGES (stop request, copy starts and flags).</summary>
    public const int CommandsFirst = 295;

    /// <summary>
    /// While a reply is sent, from its check's start to its last chunk (<see cref="ChunkPart"/>): COVERED, a pointer to
    /// the last reply character the check has covered (OP_PANEL writes it), and SENT, a pointer to the last character
    /// handed to XMT (the next chunk's XMT table). They are SAVE's AC0 and AC1 double words: the reply's check keeps only
    /// AC2 and AC3 between its slices, and no request is served until the reply is out.
    /// </summary>
    public const int Covered = Save, Sent = Save + 4;

    /// <summary>N .. LIST as one double word while a check is computed (see the class summary).</summary>
    public const int Scratch = N;

    public int BufferStart { get; } = bufferStart;

    public int LastByte => BufferStart + CopyArea + CopyBytes - 1;

    /// <summary>"VB7900" for buffer byte 0.</summary>
    public string B(int offset) => "VB" + Abs(offset);

    public string W(int offset) => "VW" + Abs(offset);

    public string Dw(int offset) => "VD" + Abs(offset);

    public string Bit(int offset, int bit) => $"V{Abs(offset)}.{bit.ToString(CultureInfo.InvariantCulture)}";

    public string Ptr(int offset) => "&VB" + Abs(offset);

    /// <summary>The symbol table: every named byte of the footprint (the blocks' names are not symbols).</summary>
    public IReadOnlyList<(string Symbol, string Address, string Comment)> Symbols =>
    [
        ("OP_BUF", B(0), "Panel handler: receive/transmit buffer, 256 bytes (byte 0 = character count)"),
        ("OP_N", B(N), "Panel handler: item COUNT of a READ or DEFINE LIST (station byte while decoding; scratch while checking)"),
        ("OP_I", B(I), "Panel handler: item loop counter (sequence byte while decoding; scratch while checking)"),
        ("OP_CMD", B(Cmd), "Panel handler: command code of the request"),
        ("OP_LIST", B(List), "Panel handler: LIST id of DEFINE/READ LIST; reply STATUS code"),
        ("OP_REQCHECK", W(ReqCheck), "Panel handler: CRC of the request being answered (REQCHECK of the reply)"),
        ("OP_MAXD", B(MaxD), "Panel handler: largest data length of the stored READ lists"),
        ("OP_LAST_FREE", B(LastFree), "Panel handler: last buffer byte below the stored lists (255 = none)"),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_START{n}", B(Start1 + n - 1), $"Panel handler: first buffer byte of READ list {n}")),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_LCOUNT{n}", B(LCount1 + n - 1), $"Panel handler: item count of READ list {n} (0 = not defined)")),
        ("OP_STEP", B(Step), "Panel handler: 0 = idle, else where OP_PANEL goes on with the request in the next scan"),
        ("OP_BUDGET", B(Budget), "Panel handler: loop passes left in this scan"),
        ("OP_CHUNK", W(Chunk), "Panel handler: characters of this pass over the frame"),
        .. Enumerable.Range(0, 4).Select(n => ($"OP_AC{n}", Dw(Save + (4 * n)), $"Panel handler: AC{n} kept between scans{SaveWhileSending(n)}")),
        ("OP_CRC", W(Crc), "Panel handler: CRC-16 register of the frame check"),
        ("OP_D", B(D), "Panel handler: sum of the item lengths; bit mask of WRITE BIT"),
        .. ChangesSymbols,
    ];

    private static string SaveWhileSending(int accumulator) => accumulator switch
    {
        0 => "; while a reply is sent: COVERED, pointer to its last character the check has covered",
        1 => "; while a reply is sent: SENT, pointer to its last character handed to XMT",
        _ => "",
    };

    private string Abs(int offset) => (BufferStart + offset).ToString(CultureInfo.InvariantCulture);
}

using System.Globalization;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The work bytes of 08 READ CHANGES and 07 STOP (from <see cref="CommandsFirst"/>) and the copy area after the work
/// bytes (docs/protocol-v2.md, "READ CHANGES"). Per list id: CSTART, the copy's first byte in the copy area (255 = no
/// copy), and CD, the list's data length D (at most 124) with bit 7 set while the copy holds what the last reply
/// reported. Copies are allocated upwards from copy byte 0 in definition order (CFREE = the next free copy byte); the
/// lists are only ever cleared all together, so there are no holes. While a READ CHANGES is compared, the CRC word
/// (free between the request's check and the reply's) holds INDEX and VALUE, so one HTA writes a pair.
/// </summary>
public sealed partial class HandlerLayout
{
    /// <summary>Offsets from the buffer start.</summary>
    public const int StopState = CommandsFirst, CFree = StopState + 1, CStart1 = CFree + 1, CD1 = CStart1 + 4, K = CD1 + 4,
        CLeft = K + 1, Entry = CLeft + 1, PairIndex = Crc, PairValue = Crc + 1;

    /// <summary>The work bytes READ CHANGES (08 and 09) and STOP use of their own.</summary>
    public const int ChangesBytes = 256 + WorkBytes - CommandsFirst;

    /// <summary>OP_STOP bit 7: SM0.7 (mode switch at RUN) as the last scan saw it, for the switch's edges.</summary>
    public const int RunSeenBit = 7;

    /// <summary>
    /// OP_STOP bit 2: the reply is on its way, its reply delay or a chunk pending, so that routine's end sends what the
    /// check has covered by then; clear while the transmitter waits for OP_PANEL (<see cref="ChunkPart"/>).
    /// </summary>
    public const int SendingBit = 2;

    /// <summary>CD bit 7: the copy is valid.</summary>
    public const int CopyValid = 0x80;

    /// <summary>CSTART of a list without a copy: no copy can start there (D >= 1 and the area has at most 255 bytes).</summary>
    public const int NoCopy = 255;

    /// <summary>Offset of the copy area: right after the work bytes.</summary>
    public const int CopyArea = 256 + WorkBytes;

    /// <summary>V bytes of the copy area (0-255).</summary>
    public int CopyBytes { get; } = copyBytes;

    private IEnumerable<(string Symbol, string Address, string Comment)> ChangesSymbols =>
    [
        ("OP_STOP", B(StopState), "Panel handler: bit 0 = STOP reply built, bit 1 = STOP reply sent, bit 2 = reply chunk or delay pending, bit 7 = SM0.7 in the last scan"),
        ("OP_CFREE", B(CFree), "Panel handler: first free byte of the READ CHANGES copy area"),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_CSTART{n}", B(CStart1 + n - 1), $"Panel handler: copy of list {n}: its first byte in the copy area (255 = no copy)")),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_CD{n}", B(CD1 + n - 1), $"Panel handler: data bytes of list {n}; bit 7 = its copy holds what the last reply reported")),
        ("OP_K", B(K), "Panel handler: READ CHANGES pairs so far"),
        ("OP_CLEFT", B(CLeft), "Panel handler: READ CHANGES bytes left in the current item"),
        ("OP_ENTRY", B(Entry), "Panel handler: READ CHANGES OF LISTS: buffer byte of the next list's entry"),
        .. CopyBytes == 0 ? [] : new[] { ("OP_COPIES", B(CopyArea), $"Panel handler: READ CHANGES copy area, {CopyBytes.ToString(CultureInfo.InvariantCulture)} bytes") },
    ];
}

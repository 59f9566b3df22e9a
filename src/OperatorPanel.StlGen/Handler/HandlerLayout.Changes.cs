using System.Globalization;

namespace OperatorPanel.StlGen.Handler;

/// <summary>
/// The work bytes of 08 READ CHANGES and 07 STOP, after the framing's work bytes, and the copy area after them
/// (docs/protocol.md, "READ CHANGES"). Per list id: the copy's first byte in the copy area, the list's data length D
/// and whether the copy holds what the last reply reported; the copies are allocated upwards from copy byte 0 in
/// definition order (CFREE = the next free copy byte), and since the lists are only ever cleared all together there
/// are no holes. INDEX and VALUE are adjacent so one HTA writes a pair.
/// </summary>
public sealed partial class HandlerLayout
{
    /// <summary>Offsets from the buffer start.</summary>
    public const int ChangesFirst = 292, CFree = ChangesFirst, CStart1 = CFree + 1, CD1 = CStart1 + 4, CValid1 = CD1 + 4,
        K = CValid1 + 4, PairIndex = K + 1, Value = PairIndex + 1, CLeft = Value + 1, StopState = CLeft + 1;

    /// <summary>The work bytes of READ CHANGES and STOP.</summary>
    public const int ChangesBytes = StopState + 1 - ChangesFirst;

    /// <summary>CSTART of a list without a copy: no copy can start there (D >= 1 and the area has at most 255 bytes).</summary>
    public const int NoCopy = 255;

    /// <summary>Offset of the copy area: right after the work bytes.</summary>
    public const int CopyArea = 256 + WorkBytes;

    /// <summary>V bytes of the copy area (0-255).</summary>
    public int CopyBytes { get; } = copyBytes;

    private IEnumerable<(string Symbol, string Address, string Comment)> ChangesSymbols =>
    [
        ("OP_CFREE", B(CFree), "Panel handler: first free byte of the READ CHANGES copy area"),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_CSTART{n}", B(CStart1 + n - 1), $"Panel handler: copy of list {n}: its first byte in the copy area (255 = no copy)")),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_CD{n}", B(CD1 + n - 1), $"Panel handler: data bytes of list {n}")),
        .. Enumerable.Range(1, 4).Select(n => ($"OP_CVALID{n}", B(CValid1 + n - 1), $"Panel handler: 1 = the copy of list {n} holds what the last reply reported")),
        ("OP_K", B(K), "Panel handler: READ CHANGES pairs so far"),
        ("OP_INDEX", B(PairIndex), "Panel handler: READ CHANGES byte index in the list's data"),
        ("OP_VALUE", B(Value), "Panel handler: READ CHANGES value of a changed byte"),
        ("OP_CLEFT", B(CLeft), "Panel handler: READ CHANGES bytes left in the current item"),
        ("OP_STOP", B(StopState), "Panel handler: bit 0 = STOP reply built, bit 1 = STOP reply sent"),
        .. CopyBytes == 0 ? [] : new[] { ("OP_COPIES", B(CopyArea), $"Panel handler: READ CHANGES copy area, {CopyBytes.ToString(CultureInfo.InvariantCulture)} bytes") },
    ];
}

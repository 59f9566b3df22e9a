using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Cli.Bench;

/// <summary>
/// Frame sizes of the seed paper's own protocol (seed 000 §8, Table 1 and the listing for &lt;MWxx?&gt;), which reads
/// one item per command. Numbers inside the frames are binary: "xx is a 2-byte long number", z/zz/zzzz are the raw
/// data bytes, y and the bit value are one character. The listing checks "if 7 characters were received" for
/// &lt;MWxx?&gt; and sends 9 (MOVB 9, VB150) for &lt;MWxx=zz&gt;, which fixes the pattern:
/// <code>
/// command          request               chars   reply                   chars
/// IBx / QBx byte   &lt; I B x ? &gt;            6       &lt; I B x = z &gt;            7     (x one character: IB0, IB2, QB0)
/// MBxx / VBxx      &lt; M B xx ? &gt;           7       &lt; M B xx = z &gt;           8
/// MWxx / VWxx      &lt; M W xx ? &gt;           7       &lt; M W xx = zz &gt;          9     (the listing)
/// MDxx / VDxx      &lt; M D xx ? &gt;           7       &lt; M D xx = zzzz &gt;       11
/// Mxx.y / Vxx.y    &lt; M xx . y ? &gt;         8       &lt; M xx . y = z &gt;         9
/// </code>
/// These frames are not safely framed: a data or address byte equal to '&gt;' ends them early. That is why this
/// panel's protocol sends hex and pays two characters per data byte.
/// </summary>
internal static class SeedFrameSizes
{
    public static int RequestChars(PlcAddress address) => address switch
    {
        { Area: MemoryArea.I or MemoryArea.Q } => 6,
        { Width: AccessWidth.Bit } => 8,
        _ => 7,
    };

    public static int ReplyChars(PlcAddress address) => address switch
    {
        { Area: MemoryArea.I or MemoryArea.Q } => 7,
        { Width: AccessWidth.Bit } => 9,
        _ => 7 + address.Width.ByteCount(),
    };
}

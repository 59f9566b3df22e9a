namespace OperatorPanel.Core.Transport.Serial;

/// <summary>
/// Where the termios fields sit and what the flag bits are: glibc Linux (tcflag_t = 32 bits, Bxxx speed codes) and
/// macOS (tcflag_t = 64 bits, speed_t = the baud rate itself). Values from &lt;bits/termios*.h&gt; and &lt;sys/termios.h&gt;.
/// </summary>
internal sealed record UnixTermiosLayout(
    int IFlagOffset,
    int CFlagOffset,
    int FlagSize,
    int OpenFlags,
    uint IxOff,
    uint IxAny,
    uint CSize,
    uint Cs7,
    uint Cs8,
    uint CStopB,
    uint CRead,
    uint ParEnb,
    uint ParOdd,
    uint CLocal,
    uint CRtsCts,
    int EAgain,
    int TciFlush,
    IReadOnlyDictionary<int, nuint> Speeds)
{
    /// <summary>Large enough for either OS's struct termios (60 bytes on Linux, 72 on macOS).</summary>
    public const int BufferSize = 256;

    public const int TcsaNow = 0;

    /// <summary>O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC.</summary>
    public static UnixTermiosLayout Linux { get; } = new(
        IFlagOffset: 0, CFlagOffset: 8, FlagSize: 4, OpenFlags: 0x2 | 0x100 | 0x800 | 0x80000,
        IxOff: 0x1000, IxAny: 0x800, CSize: 0x30, Cs7: 0x20, Cs8: 0x30, CStopB: 0x40, CRead: 0x80,
        ParEnb: 0x100, ParOdd: 0x200, CLocal: 0x800, CRtsCts: 0x80000000, EAgain: 11, TciFlush: 0,
        Speeds: new Dictionary<int, nuint>
        {
            [1200] = 0x9,
            [2400] = 0xB,
            [4800] = 0xC,
            [9600] = 0xD,
            [19200] = 0xE,
            [38400] = 0xF,
            [57600] = 0x1001,
            [115200] = 0x1002,
        });

    public static UnixTermiosLayout MacOS { get; } = new(
        IFlagOffset: 0, CFlagOffset: 16, FlagSize: 8, OpenFlags: 0x2 | 0x20000 | 0x4 | 0x1000000,
        IxOff: 0x400, IxAny: 0x800, CSize: 0x300, Cs7: 0x200, Cs8: 0x300, CStopB: 0x400, CRead: 0x800,
        ParEnb: 0x1000, ParOdd: 0x2000, CLocal: 0x8000, CRtsCts: 0x30000, EAgain: 35, TciFlush: 1,
        Speeds: new Dictionary<int, nuint>
        {
            [1200] = 1200,
            [2400] = 2400,
            [4800] = 4800,
            [9600] = 9600,
            [19200] = 19200,
            [38400] = 38400,
            [57600] = 57600,
            [115200] = 115200,
        });

    public static UnixTermiosLayout Current => OperatingSystem.IsMacOS() ? MacOS : Linux;

    public uint ReadFlag(byte[] termios, int offset) =>
        BitConverter.ToUInt32(termios, offset + (BitConverter.IsLittleEndian ? 0 : FlagSize - 4));

    /// <summary>Every flag we touch is in the low 32 bits, so the upper half of a 64-bit macOS flag stays as is.</summary>
    public void WriteFlag(byte[] termios, int offset, uint value) =>
        BitConverter.TryWriteBytes(termios.AsSpan(offset + (BitConverter.IsLittleEndian ? 0 : FlagSize - 4), 4), value);
}

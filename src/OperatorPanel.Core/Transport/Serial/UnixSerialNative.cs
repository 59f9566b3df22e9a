using System.Runtime.InteropServices;

namespace OperatorPanel.Core.Transport.Serial;

/// <summary>
/// libc calls for a serial tty on Linux and macOS. termios is passed as an opaque buffer whose layout
/// <see cref="UnixTermiosLayout"/> describes, so no struct differs per OS here. File descriptors travel as
/// pointer-sized handles; the C <c>int</c> is their low half on every supported 64-bit ABI.
/// DllImport, not LibraryImport: Core builds without unsafe code, and these signatures need no marshalling stubs.
/// </summary>
internal static class UnixSerialNative
{
    private const string LibC = "libc";

    public const short PollIn = 0x001;
    public const short PollOut = 0x004;
    public const short PollErr = 0x008;
    public const short PollHup = 0x010;
    public const short PollNval = 0x020;

    public const int EIntr = 4;

    [StructLayout(LayoutKind.Sequential)]
    public struct PollFd
    {
        public int Fd;
        public short Events;
        public short Revents;
    }

    /// <summary><paramref name="nulTerminatedUtf8Path"/>: the path as UTF-8 bytes ending in 0, as the kernel wants it.</summary>
    [DllImport(LibC, EntryPoint = "open", SetLastError = true)]
    public static extern int Open(byte[] nulTerminatedUtf8Path, int flags);

    [DllImport(LibC, EntryPoint = "tcgetattr", SetLastError = true)]
    public static extern int TcGetAttr(SafeHandle fd, byte[] termios);

    [DllImport(LibC, EntryPoint = "tcsetattr", SetLastError = true)]
    public static extern int TcSetAttr(SafeHandle fd, int optionalActions, byte[] termios);

    [DllImport(LibC, EntryPoint = "cfmakeraw")]
    public static extern void CfMakeRaw(byte[] termios);

    /// <summary>speed_t is unsigned int on Linux and unsigned long on macOS; both travel in one register.</summary>
    [DllImport(LibC, EntryPoint = "cfsetispeed", SetLastError = true)]
    public static extern int CfSetISpeed(byte[] termios, nuint speed);

    [DllImport(LibC, EntryPoint = "cfsetospeed", SetLastError = true)]
    public static extern int CfSetOSpeed(byte[] termios, nuint speed);

    [DllImport(LibC, EntryPoint = "tcflush", SetLastError = true)]
    public static extern int TcFlush(SafeHandle fd, int queueSelector);

    /// <summary>ioctl is variadic; the one-pointer form is called only on Linux x64/arm64 where that ABI matches.</summary>
    [DllImport(LibC, EntryPoint = "ioctl", SetLastError = true)]
    public static extern int IoctlInt(SafeHandle fd, nuint request, ref int argument);

    [DllImport(LibC, EntryPoint = "poll", SetLastError = true)]
    public static extern int Poll(ref PollFd fds, nuint count, int timeoutMilliseconds);

    [DllImport(LibC, EntryPoint = "read", SetLastError = true)]
    public static extern nint Read(SafeHandle fd, ref byte buffer, nint count);

    [DllImport(LibC, EntryPoint = "write", SetLastError = true)]
    public static extern nint Write(SafeHandle fd, ref readonly byte buffer, nint count);
}

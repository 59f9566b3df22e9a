using System.Runtime.InteropServices;
using static OperatorPanel.Core.Transport.Serial.UnixSerialNative;

namespace OperatorPanel.Core.Transport.Serial;

/// <summary>Puts an open tty into the raw 7/8-bit, parity, 1/2 stop bit mode of <see cref="SerialSettings"/>.</summary>
internal static class UnixTermiosSetup
{
    private const nuint LinuxTiocExcl = 0x540C;
    private const nuint LinuxTiocMBis = 0x5416;
    private const int TiocMDtr = 0x002;
    private const int TiocMRts = 0x004;

    public static void Apply(SafeHandle fd, SerialSettings settings, UnixTermiosLayout layout)
    {
        var port = settings.PortName;
        if (!layout.Speeds.TryGetValue(settings.BaudRate, out var speed))
        {
            throw SerialPortErrors.Unavailable(port, $"baud rate {settings.BaudRate} is not supported (1200-115200)");
        }

        var termios = new byte[UnixTermiosLayout.BufferSize];
        Check(TcGetAttr(fd, termios), port, "read settings (tcgetattr; is it a serial device?)");
        CfMakeRaw(termios);

        // cfmakeraw clears IXON but not IXOFF/IXANY: software flow control would eat 0x11/0x13 bytes.
        var iflag = layout.ReadFlag(termios, layout.IFlagOffset) & ~(layout.IxOff | layout.IxAny);
        layout.WriteFlag(termios, layout.IFlagOffset, iflag);

        var cflag = layout.ReadFlag(termios, layout.CFlagOffset)
            & ~(layout.CSize | layout.ParEnb | layout.ParOdd | layout.CStopB | layout.CRtsCts);
        cflag |= (settings.DataBits == 7 ? layout.Cs7 : layout.Cs8) | layout.CLocal | layout.CRead;
        cflag |= settings.Parity switch
        {
            Parity.Even => layout.ParEnb,
            Parity.Odd => layout.ParEnb | layout.ParOdd,
            _ => 0u,
        };
        cflag |= settings.StopBits == 2 ? layout.CStopB : 0u;
        layout.WriteFlag(termios, layout.CFlagOffset, cflag);

        Check(CfSetISpeed(termios, speed), port, "set input baud rate");
        Check(CfSetOSpeed(termios, speed), port, "set output baud rate");
        Check(TcSetAttr(fd, UnixTermiosLayout.TcsaNow, termios), port, "apply settings (tcsetattr)");
        TryLinuxModemLines(fd);
    }

    /// <summary>
    /// Port-powered RS-232/RS-485 converters draw their supply from DTR and RTS. Linux raises both on open already;
    /// asserting them again helps drivers that don't. Pseudo-terminals have no modem lines, so failure is ignored.
    /// Exclusive mode (TIOCEXCL) keeps a second program off the bus; a refusal is ignored for the same reason.
    /// macOS raises the lines on open too, and its variadic ioctl ABI differs, so it is not called there.
    /// </summary>
    private static void TryLinuxModemLines(SafeHandle fd)
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }

        var lines = TiocMDtr | TiocMRts;
        _ = IoctlInt(fd, LinuxTiocMBis, ref lines);
        var unused = 0;
        _ = IoctlInt(fd, LinuxTiocExcl, ref unused);
    }

    private static void Check(int result, string port, string action)
    {
        if (result != 0)
        {
            throw SerialPortErrors.Unix(port, action, Marshal.GetLastPInvokeError());
        }
    }
}

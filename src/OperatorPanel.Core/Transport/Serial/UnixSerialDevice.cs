using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;
using static OperatorPanel.Core.Transport.Serial.UnixSerialNative;

namespace OperatorPanel.Core.Transport.Serial;

/// <summary>
/// A tty on Linux or macOS through termios: raw mode, no flow control, CLOCAL so a missing DCD (pseudo-terminals,
/// 3-wire RS-232) never blocks. The descriptor stays non-blocking; poll() provides the timeouts.
/// </summary>
internal sealed class UnixSerialDevice : ISerialDevice
{
    /// <summary>Longest single poll(): cancellation and close are noticed within this.</summary>
    private const int SliceMilliseconds = 50;

    private readonly SafeFileHandle _fd;
    private readonly string _portName;
    private readonly UnixTermiosLayout _layout;

    private UnixSerialDevice(SafeFileHandle fd, string portName, UnixTermiosLayout layout)
    {
        _fd = fd;
        _portName = portName;
        _layout = layout;
    }

    public static UnixSerialDevice Open(SerialSettings settings)
    {
        var layout = UnixTermiosLayout.Current;
        var path = System.Text.Encoding.UTF8.GetBytes(settings.PortName + "\0");
        var fd = UnixSerialNative.Open(path, layout.OpenFlags);
        if (fd < 0)
        {
            throw SerialPortErrors.Unix(settings.PortName, "open", Marshal.GetLastPInvokeError());
        }

        var device = new UnixSerialDevice(new SafeFileHandle(fd, ownsHandle: true), settings.PortName, layout);
        try
        {
            UnixTermiosSetup.Apply(device._fd, settings, layout);
            return device;
        }
        catch (PlcCommunicationException)
        {
            device.Dispose();
            throw;
        }
    }

    public int Read(Span<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var deadline = Environment.TickCount64 + (long)Math.Ceiling(timeout.TotalMilliseconds);
        while (true)
        {
            var remaining = deadline - Environment.TickCount64;
            if (!WaitFor(PollIn, remaining, cancellationToken))
            {
                if (remaining <= 0)
                {
                    return 0;
                }

                continue;
            }

            var count = UnixSerialNative.Read(_fd, ref MemoryMarshal.GetReference(buffer), buffer.Length);
            if (count > 0)
            {
                return (int)count;
            }

            if (count == 0)
            {
                throw SerialPortErrors.Unavailable(_portName, "end of file: the device vanished (hang-up)");
            }

            ThrowUnlessRetryable("read", Marshal.GetLastPInvokeError());
        }
    }

    public void Write(ReadOnlySpan<byte> data, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var deadline = Environment.TickCount64 + (long)Math.Ceiling(timeout.TotalMilliseconds);
        while (!data.IsEmpty)
        {
            var count = UnixSerialNative.Write(_fd, in MemoryMarshal.GetReference(data), data.Length);
            if (count > 0)
            {
                data = data[(int)count..];
                continue;
            }

            if (count < 0)
            {
                ThrowUnlessRetryable("write", Marshal.GetLastPInvokeError());
            }

            var remaining = deadline - Environment.TickCount64;
            if (!WaitFor(PollOut, remaining, cancellationToken) && remaining <= 0)
            {
                throw SerialPortErrors.Unavailable(_portName, $"write did not complete within {timeout.TotalMilliseconds:0} ms");
            }
        }
    }

    public void DiscardInput()
    {
        if (TcFlush(_fd, _layout.TciFlush) != 0)
        {
            throw SerialPortErrors.Unix(_portName, "discard input (tcflush)", Marshal.GetLastPInvokeError());
        }
    }

    public void Dispose() => _fd.Dispose();

    /// <summary>One poll() of at most a slice; true when the descriptor is ready (or hung up, which read reports).</summary>
    private bool WaitFor(short events, long remainingMilliseconds, CancellationToken cancellationToken)
    {
        cancellationToken.ThrowIfCancellationRequested();
        var added = false;
        _fd.DangerousAddRef(ref added);
        try
        {
            var poll = new PollFd { Fd = (int)_fd.DangerousGetHandle(), Events = events };
            var slice = (int)Math.Clamp(remainingMilliseconds, 0, SliceMilliseconds);
            var ready = Poll(ref poll, 1, slice);
            if (ready < 0)
            {
                ThrowUnlessRetryable("poll", Marshal.GetLastPInvokeError());
                return false;
            }

            if ((poll.Revents & PollNval) != 0)
            {
                throw SerialPortErrors.Unavailable(_portName, "the descriptor is no longer valid");
            }

            return ready > 0;
        }
        finally
        {
            if (added)
            {
                _fd.DangerousRelease();
            }
        }
    }

    private void ThrowUnlessRetryable(string action, int errno)
    {
        if (errno != EIntr && errno != _layout.EAgain)
        {
            throw SerialPortErrors.Unix(_portName, action, errno);
        }
    }
}

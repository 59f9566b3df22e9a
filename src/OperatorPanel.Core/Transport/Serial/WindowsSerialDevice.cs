using System.Runtime.InteropServices;
using System.Runtime.Versioning;
using Microsoft.Win32.SafeHandles;
using static OperatorPanel.Core.Transport.Serial.WindowsSerialNative;

namespace OperatorPanel.Core.Transport.Serial;

/// <summary>
/// A COM port through kernel32. Reads use the "return as soon as one byte is there, else after the constant"
/// COMMTIMEOUTS mode (interval = multiplier = MAXDWORD), in slices so cancellation and close are noticed. A
/// synchronous handle serialises ReadFile and WriteFile, so a write waits at most one read slice.
/// </summary>
[SupportedOSPlatform("windows")]
internal sealed class WindowsSerialDevice : ISerialDevice
{
    private const uint SliceMilliseconds = 50;

    // DCB bit fields: fBinary, fParity, fDtrControl = DTR_CONTROL_ENABLE (bits 4-5 = 01), fRtsControl =
    // RTS_CONTROL_ENABLE (bits 12-13 = 01); every flow-control and error-replacement bit stays clear.
    private const uint FlagBinary = 1u << 0;
    private const uint FlagParity = 1u << 1;
    private const uint FlagDtrEnable = 1u << 4;
    private const uint FlagRtsEnable = 1u << 12;

    private readonly SafeFileHandle _handle;
    private readonly string _portName;
    private readonly Lock _timeoutsLock = new();
    private CommTimeouts _timeouts;

    private WindowsSerialDevice(SafeFileHandle handle, string portName, CommTimeouts timeouts)
    {
        _handle = handle;
        _portName = portName;
        _timeouts = timeouts;
    }

    public static WindowsSerialDevice Open(SerialSettings settings)
    {
        var port = settings.PortName;
        var handle = CreateFile(@"\\.\" + port, GenericRead | GenericWrite, 0, 0, OpenExisting, 0, 0);
        if (handle.IsInvalid)
        {
            var error = Marshal.GetLastPInvokeError();
            handle.Dispose();
            throw SerialPortErrors.Windows(port, "open", error);
        }

        var dcb = new Dcb { DcbLength = (uint)Marshal.SizeOf<Dcb>() };
        var timeouts = new CommTimeouts
        {
            ReadIntervalTimeout = MaxDword,
            ReadTotalTimeoutMultiplier = MaxDword,
            ReadTotalTimeoutConstant = SliceMilliseconds,
            WriteTotalTimeoutMultiplier = (uint)Math.Ceiling(settings.CharacterTime.TotalMilliseconds * 2),
            WriteTotalTimeoutConstant = 500,
        };
        if (!GetCommState(handle, ref dcb) || !SetCommState(handle, ref Configure(ref dcb, settings))
            || !SetCommTimeouts(handle, ref timeouts))
        {
            var error = Marshal.GetLastPInvokeError();
            handle.Dispose();
            throw SerialPortErrors.Windows(port, "configure", error);
        }

        return new WindowsSerialDevice(handle, port, timeouts);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var deadline = Environment.TickCount64 + (long)Math.Ceiling(timeout.TotalMilliseconds);
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            var remaining = deadline - Environment.TickCount64;
            SetReadSlice((uint)Math.Clamp(remaining, 1, SliceMilliseconds));
            if (!ReadFile(_handle, ref MemoryMarshal.GetReference(buffer), buffer.Length, out var read, 0))
            {
                throw SerialPortErrors.Windows(_portName, "read", Marshal.GetLastPInvokeError());
            }

            if (read > 0 || remaining <= SliceMilliseconds)
            {
                return read;
            }
        }
    }

    public void Write(ReadOnlySpan<byte> data, TimeSpan timeout, CancellationToken cancellationToken)
    {
        cancellationToken.ThrowIfCancellationRequested();
        if (!WriteFile(_handle, in MemoryMarshal.GetReference(data), data.Length, out var written, 0))
        {
            throw SerialPortErrors.Windows(_portName, "write", Marshal.GetLastPInvokeError());
        }

        if (written < data.Length)
        {
            throw SerialPortErrors.Unavailable(_portName, $"write sent {written} of {data.Length} bytes in time");
        }
    }

    public void DiscardInput()
    {
        if (!PurgeComm(_handle, PurgeRxClear))
        {
            throw SerialPortErrors.Windows(_portName, "discard input (PurgeComm)", Marshal.GetLastPInvokeError());
        }
    }

    public void Dispose() => _handle.Dispose();

    private static ref Dcb Configure(ref Dcb dcb, SerialSettings settings)
    {
        dcb.BaudRate = (uint)settings.BaudRate;
        dcb.ByteSize = (byte)settings.DataBits;
        dcb.Parity = settings.Parity switch { Parity.Odd => 1, Parity.Even => 2, _ => 0 };
        dcb.StopBits = settings.StopBits == 2 ? (byte)2 : (byte)0;
        dcb.Flags = FlagBinary | FlagDtrEnable | FlagRtsEnable | (settings.Parity == Parity.None ? 0 : FlagParity);
        return ref dcb;
    }

    private void SetReadSlice(uint milliseconds)
    {
        lock (_timeoutsLock)
        {
            if (_timeouts.ReadTotalTimeoutConstant == milliseconds)
            {
                return;
            }

            _timeouts.ReadTotalTimeoutConstant = milliseconds;
            if (!SetCommTimeouts(_handle, ref _timeouts))
            {
                throw SerialPortErrors.Windows(_portName, "set read timeout", Marshal.GetLastPInvokeError());
            }
        }
    }
}

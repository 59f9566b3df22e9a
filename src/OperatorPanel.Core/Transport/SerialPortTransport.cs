using System.IO.Ports;
using Serilog;
using Serilog.Core;
using PortParity = System.IO.Ports.Parity;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// The PC's serial port (PC/PPI cable, USB-RS485 adapter, FT232R radio module): a thin adapter over
/// <see cref="SerialPort"/>, and the one file of the product that touches System.IO.Ports. Reads run on a dedicated
/// thread: on Windows blocking reads in short ReadTimeout slices (there the stream's async reads ignore ReadTimeout and
/// cancellation); on Linux/macOS through <see cref="OutstandingStreamRead"/> (there the timed read can drop bytes).
/// Writes block on a second thread, so a reply can be sent while a read waits. Once the device has failed (unplugged
/// adapter, closed pty) every later call fails the same way: the library's Unix I/O loop stops for good after a
/// hang-up, and later reads would otherwise just time out. A failed transport reports itself not open, and opening it
/// again closes the dead port and opens the device afresh (the link reconnects that way). Failures are <see cref="PlcCommunicationException"/> of
/// kind <see cref="PlcErrorKind.PortUnavailable"/> naming the port (<see cref="SerialPortErrors"/>). One program per port:
/// opening claims the port (<see cref="PortLock"/>) and a port another program holds is refused naming that program;
/// closing never holds the caller longer than <see cref="BoundedClose.Limit"/>. Over 300 lines: the whole adapter (open,
/// read, write, close) stays in the one file allowed to touch System.IO.Ports.
/// </summary>
public sealed class SerialPortTransport : ITransport
{
    /// <summary>Longest single blocking read: cancellation and close are noticed within this.</summary>
    private const int ReadSliceMilliseconds = 50;

    /// <summary>Slack on top of twice the line time of a write, for USB scheduling and driver queues.</summary>
    private static readonly TimeSpan WriteSlack = TimeSpan.FromMilliseconds(500);

    private readonly SerialSettings _settings;
    private readonly ILogger _logger;
    private readonly TimeProvider _time;
    private readonly string _lockFolder;
    private readonly CancellationTokenSource _closing = new();
    private PortLock? _lock;
    private SerialIoLane? _readLane;
    private SerialIoLane? _writeLane;
    private SerialPort? _port;
    private OutstandingStreamRead? _unixRead;
    private string? _failure;

    /// <param name="settings">The port and its line settings.</param>
    /// <param name="logger">Where an abandoned close is reported.</param>
    /// <param name="time">The clock of the close's time limit.</param>
    /// <param name="lockFolder">Where the port lock goes; <see cref="PortLock.DefaultFolder"/> by default.</param>
    public SerialPortTransport(SerialSettings settings, ILogger? logger = null, TimeProvider? time = null, string? lockFolder = null)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentOutOfRangeException.ThrowIfLessThan(settings.DataBits, 7);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(settings.DataBits, 8);
        ArgumentOutOfRangeException.ThrowIfLessThan(settings.StopBits, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(settings.StopBits, 2);
        _settings = settings;
        _logger = logger ?? Logger.None;
        _time = time ?? TimeProvider.System;
        _lockFolder = lockFolder ?? PortLock.DefaultFolder;
    }

    public string Name => _settings.PortName;

    /// <summary>False after a device failure too: the descriptor is dead even though the port object still exists.</summary>
    public bool IsOpen => _port is not null && _failure is null && !_closing.IsCancellationRequested;

    public async Task OpenAsync(CancellationToken cancellationToken)
    {
        ObjectDisposedException.ThrowIf(_closing.IsCancellationRequested, this);
        if (_failure is not null)
        {
            DropFailedPort();
        }

        if (_port is not null)
        {
            throw new InvalidOperationException($"{Name} is already open");
        }

        if (_lock is null && !PortLock.TryAcquire(Name, _lockFolder, out _lock, out var inUse))
        {
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, inUse);
        }

        var readLane = new SerialIoLane("serial read " + Name);
        try
        {
            _port = await readLane.Run(OpenPort).ConfigureAwait(false);
            _unixRead = OperatingSystem.IsWindows() ? null : new OutstandingStreamRead(_port.BaseStream);
        }
        catch (PlcCommunicationException)
        {
            await readLane.StopAsync().ConfigureAwait(false);
            _lock?.Dispose();
            _lock = null;
            throw;
        }

        _readLane = readLane;
        _writeLane = new SerialIoLane("serial write " + Name);
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        var (port, lane) = Ensure(_writeLane);
        var timeout = (_settings.CharacterTime * data.Length * 2) + WriteSlack;
        return RunOnLaneAsync(lane, token =>
        {
            token.ThrowIfCancellationRequested();
            var milliseconds = (int)Math.Ceiling(timeout.TotalMilliseconds);
            if (port.WriteTimeout != milliseconds)
            {
                port.WriteTimeout = milliseconds;
            }

            try
            {
                port.BaseStream.Write(data.Span);
            }
            catch (TimeoutException)
            {
                throw Fail(SerialPortErrors.Unavailable(Name, $"write did not complete within {milliseconds} ms"));
            }
            catch (Exception failure) when (SerialPortErrors.IsDeviceFailure(failure))
            {
                throw Fail(SerialPortErrors.Vanished(Name, "write", failure));
            }

            return data.Length;
        }, cancellationToken);
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(timeout, TimeSpan.Zero);
        var (port, lane) = Ensure(_readLane);
        return RunOnLaneAsync(lane, token =>
        {
            try
            {
                return _unixRead is { } unixRead ? unixRead.Read(buffer.Span, timeout, token) : ReadInSlices(port, buffer, timeout, token);
            }
            catch (Exception failure) when (SerialPortErrors.IsDeviceFailure(failure))
            {
                throw Fail(SerialPortErrors.Vanished(Name, "read", failure));
            }
        }, cancellationToken);
    }

    public void DiscardInput()
    {
        var (port, _) = Ensure(_readLane);
        try
        {
            port.DiscardInBuffer();
            _unixRead?.Discard();
        }
        catch (Exception failure) when (SerialPortErrors.IsDeviceFailure(failure))
        {
            throw Fail(SerialPortErrors.Vanished(Name, "discard input", failure));
        }
    }

    /// <summary>
    /// Stops the lanes, closes the port and releases its lock, waiting at most <see cref="BoundedClose.Limit"/>: a close
    /// that takes longer is logged and left to finish in the background (the lock goes when it does, or with the process).
    /// </summary>
    public async ValueTask DisposeAsync()
    {
        if (_closing.IsCancellationRequested)
        {
            return;
        }

        await _closing.CancelAsync().ConfigureAwait(false);
        var (lanes, port, unixRead, portLock) = (new[] { _readLane, _writeLane }, _port, _unixRead, _lock);
        var closed = await BoundedClose.RunAsync(
            async () =>
            {
                foreach (var lane in lanes)
                {
                    if (lane is not null)
                    {
                        await lane.StopAsync().ConfigureAwait(false);
                    }
                }

                port?.Dispose();
                unixRead?.Forget();
                portLock?.Dispose();
            },
            BoundedClose.Limit,
            _time).ConfigureAwait(false);
        if (closed)
        {
            _closing.Dispose();
            return;
        }

        _logger.Warning(
            "Serial port {Port}: closing took more than {Seconds} s (a USB serial driver blocking in close?); the port is abandoned and the program goes on",
            Name, BoundedClose.Limit.TotalSeconds);
    }

    /// <summary>
    /// Drops the dead port so the next open starts on a new descriptor (the returned device often has the same name but
    /// is a new file). Its lanes and its close are left to finish in the background: closing a dead descriptor can block,
    /// and reconnecting must not wait for it.
    /// </summary>
    private void DropFailedPort()
    {
        var (readLane, writeLane, port, unixRead) = (_readLane, _writeLane, _port, _unixRead);
        (_readLane, _writeLane, _port, _unixRead, _failure) = (null, null, null, null, null);
        _ = Task.Run(async () =>
        {
            foreach (var lane in new[] { readLane, writeLane })
            {
                if (lane is not null)
                {
                    await lane.StopAsync().ConfigureAwait(false);
                }
            }

            CloseDeadPort(port, unixRead);
        });
    }

    /// <summary>Closing a port whose device is gone may itself fail on the dead descriptor; the port is dropped either way.</summary>
    private static void CloseDeadPort(SerialPort? port, OutstandingStreamRead? unixRead)
    {
        try
        {
            port?.Dispose();
        }
        catch (Exception failure) when (SerialPortErrors.IsDeviceFailure(failure))
        {
            // The descriptor went with the device: nothing is left to release.
        }

        unixRead?.Forget();
    }

    /// <summary>The port names the OS publishes now, for <see cref="SerialPortDiscovery"/>; opens none.</summary>
    internal static string[] PortNamesPresent() => SerialPort.GetPortNames();

    /// <summary>
    /// Opens and configures the port: raw bytes, no handshake. On Unix a failed open is tried once more, because the
    /// library reads errno after formatting its message and so the first failure of a process can carry a stale errno
    /// (seen: 203 for a missing path, ENOENT on the second try).
    /// </summary>
    private SerialPort OpenPort()
    {
        try
        {
            return OpenOnce(_settings.Parity);
        }
        catch (ArgumentException) when (_settings.Parity != Parity.None && IsPseudoTerminal(Name))
        {
            // A Linux pty drops the parity bit from its settings, and System.IO.Ports, reading them back, refuses the
            // port once a previous open left its speed as wanted (seen with socat pairs). A pty carries bytes, not bits:
            // no parity is what it does anyway, so the port is opened so.
            return OpenOnce(Parity.None);
        }
        catch (Exception first) when (SerialPortErrors.IsOpenFailure(first) && !OperatingSystem.IsWindows())
        {
            try
            {
                return OpenOnce(_settings.Parity);
            }
            catch (Exception second) when (SerialPortErrors.IsOpenFailure(second))
            {
                throw SerialPortErrors.OpenFailed(Name, second);
            }
        }
        catch (Exception failure) when (SerialPortErrors.IsOpenFailure(failure))
        {
            throw SerialPortErrors.OpenFailed(Name, failure);
        }
    }

    /// <summary>True for a Linux pseudo-terminal (a /dev/pts/N device, or a link to one as socat makes).</summary>
    private static bool IsPseudoTerminal(string name)
    {
        if (OperatingSystem.IsWindows())
        {
            return false;
        }

        try
        {
            var target = File.ResolveLinkTarget(name, returnFinalTarget: true)?.FullName ?? name;
            return target.StartsWith("/dev/pts/", StringComparison.Ordinal);
        }
        catch (IOException)
        {
            return false;
        }
    }

    private SerialPort OpenOnce(Parity parity)
    {
        var port = new SerialPort();
        try
        {
            port.PortName = Name;
            port.BaudRate = _settings.BaudRate;
            port.Parity = ToPortParity(parity);
            port.DataBits = _settings.DataBits;
            port.StopBits = _settings.StopBits == 2 ? StopBits.Two : StopBits.One;
            port.Handshake = Handshake.None;
            port.ReadTimeout = ReadSliceMilliseconds;
            port.Open();
        }
        catch (Exception failure) when (SerialPortErrors.IsOpenFailure(failure))
        {
            port.Dispose();
            throw;
        }

        RaiseModemLines(port);
        return port;
    }

    /// <summary>
    /// Port-powered RS-232/RS-485 converters draw their supply from DTR and RTS, so both are raised. Pseudo-terminals
    /// have no modem lines and refuse with ENOTTY; the link needs none, so that refusal is not an error.
    /// </summary>
    private static void RaiseModemLines(SerialPort port)
    {
        try
        {
            port.DtrEnable = true;
            port.RtsEnable = true;
        }
        catch (IOException)
        {
            // No modem lines on this device (pty): bytes still flow.
        }
    }

    private static PortParity ToPortParity(Parity parity) => parity switch
    {
        Parity.None => PortParity.None,
        Parity.Even => PortParity.Even,
        Parity.Odd => PortParity.Odd,
    };

    /// <summary>Windows: blocking reads of at most one slice each until a byte comes or <paramref name="timeout"/> passes.</summary>
    private static int ReadInSlices(SerialPort port, Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        var deadline = Environment.TickCount64 + (long)Math.Ceiling(timeout.TotalMilliseconds);
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            var remaining = deadline - Environment.TickCount64;
            var slice = (int)Math.Clamp(remaining, 1, ReadSliceMilliseconds);
            if (port.ReadTimeout != slice)
            {
                port.ReadTimeout = slice;
            }

            try
            {
                return port.BaseStream.Read(buffer.Span);
            }
            catch (TimeoutException) when (remaining <= ReadSliceMilliseconds)
            {
                return 0;
            }
            catch (TimeoutException)
            {
                // One slice passed without a byte: look at cancellation and close, then wait on.
            }
        }
    }

    private (SerialPort Port, SerialIoLane Lane) Ensure(SerialIoLane? lane)
    {
        if (_closing.IsCancellationRequested)
        {
            throw Closed();
        }

        if (_failure is { } failure)
        {
            throw new PlcCommunicationException(PlcErrorKind.PortUnavailable, null, failure);
        }

        return _port is not null && lane is not null
            ? (_port, lane)
            : throw new InvalidOperationException($"{Name} is not open: call OpenAsync first");
    }

    /// <summary>Remembers the first device failure, so every later call reports it instead of timing out.</summary>
    private PlcCommunicationException Fail(PlcCommunicationException failure)
    {
        Interlocked.CompareExchange(ref _failure, failure.Message, null);
        return failure;
    }

    private async Task<T> RunOnLaneAsync<T>(SerialIoLane lane, Func<CancellationToken, T> operation, CancellationToken cancellationToken)
    {
        using var linked = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken, _closing.Token);
        try
        {
            return await lane.Run(() => operation(linked.Token)).ConfigureAwait(false);
        }
        catch (OperationCanceledException) when (!cancellationToken.IsCancellationRequested)
        {
            throw Closed();
        }
    }

    private PlcCommunicationException Closed() => SerialPortErrors.Unavailable(Name, "the port was closed");
}

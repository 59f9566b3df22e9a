using OperatorPanel.Core.Transport.Serial;

namespace OperatorPanel.Core.Transport;

/// <summary>
/// The PC's serial port (PC/PPI cable, USB-RS485 adapter, FT232R radio module) driven through the OS directly:
/// termios on Linux/macOS, kernel32 on Windows (the registry copy has no System.IO.Ports). Blocking device calls run
/// on two dedicated threads, one for reads and one for writes; OS errors become
/// <see cref="PlcCommunicationException"/> of kind <see cref="PlcErrorKind.PortUnavailable"/> naming the port.
/// </summary>
public sealed class SerialPortTransport : ITransport
{
    /// <summary>Slack on top of twice the line time of a write, for USB scheduling and driver queues.</summary>
    private static readonly TimeSpan WriteSlack = TimeSpan.FromMilliseconds(500);

    private readonly SerialSettings _settings;
    private readonly CancellationTokenSource _closing = new();
    private SerialIoLane? _readLane;
    private SerialIoLane? _writeLane;
    private ISerialDevice? _device;

    public SerialPortTransport(SerialSettings settings)
    {
        ArgumentNullException.ThrowIfNull(settings);
        ArgumentOutOfRangeException.ThrowIfLessThan(settings.DataBits, 7);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(settings.DataBits, 8);
        ArgumentOutOfRangeException.ThrowIfLessThan(settings.StopBits, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(settings.StopBits, 2);
        _settings = settings;
    }

    public string Name => _settings.PortName;

    public bool IsOpen => _device is not null && !_closing.IsCancellationRequested;

    public async Task OpenAsync(CancellationToken cancellationToken)
    {
        ObjectDisposedException.ThrowIf(_closing.IsCancellationRequested, this);
        if (_device is not null)
        {
            throw new InvalidOperationException($"{Name} is already open");
        }

        var readLane = new SerialIoLane("serial read " + Name);
        try
        {
            _device = await readLane.Run(OpenDevice).ConfigureAwait(false);
        }
        catch (PlcCommunicationException)
        {
            await readLane.StopAsync().ConfigureAwait(false);
            throw;
        }

        _readLane = readLane;
        _writeLane = new SerialIoLane("serial write " + Name);
    }

    public Task WriteAsync(ReadOnlyMemory<byte> data, CancellationToken cancellationToken)
    {
        var (device, lane) = Ensure(_writeLane);
        var timeout = (_settings.CharacterTime * data.Length * 2) + WriteSlack;
        return RunOnLaneAsync(lane, token =>
        {
            device.Write(data.Span, timeout, token);
            return data.Length;
        }, cancellationToken);
    }

    public Task<int> ReadAsync(Memory<byte> buffer, TimeSpan timeout, CancellationToken cancellationToken)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(timeout, TimeSpan.Zero);
        var (device, lane) = Ensure(_readLane);
        return RunOnLaneAsync(lane, token => device.Read(buffer.Span, timeout, token), cancellationToken);
    }

    public void DiscardInput() => Ensure(_readLane).Device.DiscardInput();

    public async ValueTask DisposeAsync()
    {
        if (_closing.IsCancellationRequested)
        {
            return;
        }

        await _closing.CancelAsync().ConfigureAwait(false);
        foreach (var lane in new[] { _readLane, _writeLane })
        {
            if (lane is not null)
            {
                await lane.StopAsync().ConfigureAwait(false);
            }
        }

        _device?.Dispose();
        _closing.Dispose();
    }

    private ISerialDevice OpenDevice() =>
        OperatingSystem.IsWindows() ? WindowsSerialDevice.Open(_settings) : UnixSerialDevice.Open(_settings);

    private (ISerialDevice Device, SerialIoLane Lane) Ensure(SerialIoLane? lane)
    {
        if (_closing.IsCancellationRequested)
        {
            throw Closed();
        }

        return _device is not null && lane is not null
            ? (_device, lane)
            : throw new InvalidOperationException($"{Name} is not open: call OpenAsync first");
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

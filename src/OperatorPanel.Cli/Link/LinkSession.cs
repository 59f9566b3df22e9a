using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Transport;
using Serilog;

namespace OperatorPanel.Cli.Link;

/// <summary>One bus opened for a verb: a <see cref="PlcLink"/> over a serial port, or over an in-process <see cref="DemoLine"/>.</summary>
internal sealed class LinkSession : IAsyncDisposable
{
    private readonly DemoLine? _demo;

    private LinkSession(PlcLink link, DemoLine? demo)
    {
        Link = link;
        _demo = demo;
    }

    public PlcLink Link { get; }

    public string PortName => Link.PortName;

    /// <summary>Opens <paramref name="serial"/>, or with <paramref name="demoStations"/> a demo line simulating them.</summary>
    public static LinkSession Open(
        SerialSettings serial, IReadOnlyList<(Station Station, CpuProfile Cpu)>? demoStations, ILogger log, TimeSpan? scanAllowance = null)
    {
        var demo = demoStations is null ? null : DemoLine.Start(serial.PortName, demoStations, log);
        ITransport transport = demo is null ? new SerialPortTransport(serial) : demo.PanelSide;
        var options = LinkOptions.For(serial);
        options = scanAllowance is { } scan ? options with { ScanAllowance = scan } : options;
        return new LinkSession(new PlcLink(transport, options, TimeProvider.System, log), demo);
    }

    public static LinkSession Open(LinkTarget target, ILogger log) =>
        Open(target.Serial, target.Demo ? [(target.Station, target.Cpu!)] : null, log, target.ScanAllowance);

    public async ValueTask DisposeAsync()
    {
        if (_demo is not null)
        {
            await _demo.DisposeAsync();
        }

        await Link.DisposeAsync();
    }
}

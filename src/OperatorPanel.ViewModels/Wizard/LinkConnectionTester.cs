using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Tests a link the way the panel will use it: a <see cref="Bus"/> on a <see cref="PlcLink"/> with the medium's timeouts
/// and retries (<see cref="LinkOptions.For"/>), over a transport opened for the test and closed after it, IDENTIFY through
/// its queue. The port must not be in use
/// by a running session: disconnect before testing the port the panel is connected on.
/// </summary>
public sealed class LinkConnectionTester : IConnectionTester
{
    private readonly Func<SerialSettings, ITransport> _openTransport;
    private readonly TimeProvider _time;

    /// <param name="openTransport">Makes the transport, e.g. <c>s =&gt; new SerialPortTransport(s)</c>; the link opens it.</param>
    /// <param name="time">The clock of the reply timeouts.</param>
    public LinkConnectionTester(Func<SerialSettings, ITransport> openTransport, TimeProvider time)
    {
        ArgumentNullException.ThrowIfNull(openTransport);
        ArgumentNullException.ThrowIfNull(time);
        (_openTransport, _time) = (openTransport, time);
    }

    public async Task<LinkReply> IdentifyAsync(SerialSettings link, Station station, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(link);
        await using var bus = Bus.OnDemand(new PlcLink(_openTransport(link), LinkOptions.For(link), _time), PollPlan.Empty, _time);
        return await bus.IdentifyAsync(station, cancellationToken);
    }

    /// <summary>A PPI bus over the transport with the master's default time-outs at the link's baud, one identify job through its queue.</summary>
    public async Task<PpiIdentifyOutcome> IdentifyPpiAsync(SerialSettings link, Station station, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(link);
        await using var bus = Bus.StartPpi(new PpiLink(_openTransport(link), link.BaudRate, _time), PollPlan.Empty, BusSettings.OnDemand, _time);
        return await bus.IdentifyPpiAsync(station, cancellationToken);
    }
}

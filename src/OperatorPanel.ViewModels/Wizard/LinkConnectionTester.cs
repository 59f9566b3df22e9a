using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Protocol;
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

    /// <summary>Opening a serial port: a USB adapter's driver may take a second or two.</summary>
    public static readonly TimeSpan PortOpenAllowance = TimeSpan.FromSeconds(2);

    /// <summary>
    /// The longest a test of <paramref name="link"/> can take when the link works as designed: the port opened, IDENTIFY
    /// and its retries each waiting out its reply time-out and the gap before it, and the v1 probe the link sends when
    /// nothing answered (PlcLink.V1Probe). A test still running after that is hanging in the port.
    /// </summary>
    public static TimeSpan LongestTest(SerialSettings link, Station station)
    {
        ArgumentNullException.ThrowIfNull(link);
        var options = LinkOptions.For(link);
        var identify = new IdentifyRequest(station);
        var attempt = options.ReplyTimeoutFor(identify) + options.InterFrameGap;
        return PortOpenAllowance + (attempt * (options.Retries + 2));
    }

    public async Task<LinkReply> IdentifyAsync(SerialSettings link, Station station, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(link);
        await using var bus = Bus.OnDemand(new V3Link(_openTransport(link), V3LinkOptions.For(link), _time), PollPlan.Empty, _time);
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

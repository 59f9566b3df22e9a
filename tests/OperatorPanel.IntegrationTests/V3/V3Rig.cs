using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference.V3;

namespace OperatorPanel.IntegrationTests.V3;

/// <summary>
/// A v3 bus in the line's own time: reference v3 stations (Simulator/Reference/V3) on a <see cref="V3ReferenceLine"/>,
/// the panel's <see cref="V3Link"/> over a <see cref="SimulatedLineTransport"/>, and the one bus owner started with
/// <see cref="Bus.StartV3"/>, on demand. Every request the stations received and every reply they sent is recorded
/// (command, status), and <see cref="Tamper"/> may lose or change a reply on its way to the PC.
/// </summary>
internal sealed class V3Rig : IAsyncDisposable
{
    private V3Rig(V3ReferenceLine line, Bus bus, SimulatedLineTransport transport)
    {
        (Line, Bus, Transport) = (line, bus, transport);
        line.Tamper = (request, reply) =>
        {
            Requests.Add((Command)(request[3] & 0x0F));
            Statuses.Add((ReplyStatus)reply[2]);
            return Tamper is { } tamper ? tamper((Command)(request[3] & 0x0F), reply) : reply;
        };
    }

    public V3ReferenceLine Line { get; }

    public Bus Bus { get; }

    public SimulatedLineTransport Transport { get; }

    /// <summary>The command of every request a station answered, in order.</summary>
    public List<Command> Requests { get; } = [];

    /// <summary>The STATUS of every reply a station sent, in order.</summary>
    public List<ReplyStatus> Statuses { get; } = [];

    /// <summary>Changes a reply (of the command given) before the PC gets it; null loses it.</summary>
    public Func<Command, byte[], byte[]?>? Tamper { get; set; }

    public ReferenceHandler Station(int index = 0) => Line.Stations[index];

    public static ReferenceHandler Handler(int station, HandlerShape? shape = null, bool allowStop = false) =>
        new(new HandlerSetup(new Station(station), CpuProfiles.For(CpuModel.Cpu224), shape, allowStop: allowStop));

    public static V3Rig Start(IReadOnlyList<ReferenceHandler> stations, params string[] watched)
    {
        var line = new V3ReferenceLine(stations);

        // The protocol's minimum gap, kept on the line's clock (the link's own gap waits in real time).
        var transport = new SimulatedLineTransport(line) { IdleBeforeWrite = TimeSpan.FromMilliseconds(5) };
        var options = LinkOptions.For(new SerialSettings { PortName = "simulated", BaudRate = 9600 }) with { InterFrameGap = TimeSpan.Zero };
        var link = new V3Link(transport, options, transport.Clock);
        var items = stations.SelectMany(s => watched.Select(a => new WatchedItem(s.Setup.Station, PlcAddress.Parse(a))));
        var plan = PollPlanner.Build(items, stations.ToDictionary(s => s.Setup.Station, s => s.Setup.Cpu));
        var bus = Bus.StartV3(link, plan, new BusSettings { Mode = RefreshMode.OnDemand }, transport.Clock);
        return new V3Rig(line, bus, transport);
    }

    public string Value(string address, int station = 2)
    {
        Bus.TryGetValue(new Station(station), PlcAddress.Parse(address), out var value).Should().BeTrue();
        return $"{Convert.ToHexString(value.Raw.AsSpan())} {value.Quality}";
    }

    public ValueTask DisposeAsync() => Bus.DisposeAsync();
}

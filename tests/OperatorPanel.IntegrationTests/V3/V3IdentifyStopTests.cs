using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Line;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Link.V3;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Stop;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.IntegrationTests.V3;

/// <summary>IDENTIFY, STOP and the compact handler on a v3 bus (<see cref="V3Rig"/>), and what an older handler is told.</summary>
public sealed class V3IdentifyStopTests
{
    private static readonly Station Two = new(2);

    [Fact]
    public async Task Identify_V3Handler_ReportsVersion3ItsFeaturesAndShape()
    {
        await using var rig = V3Rig.Start([V3Rig.Handler(2, allowStop: true)], "VB100");

        var reply = await rig.Bus.IdentifyAsync(Two);

        var identity = reply.Response.Should().BeOfType<IdentifyResponse>().Subject;
        (identity.ProtocolVersion, identity.StopEnabled, identity.MaxReadData).Should().Be(((byte)3, true, (byte)HandlerShape.MaxData));
        rig.Bus.IdentityOf(Two).Should().Be(identity);
    }

    [Fact]
    public async Task Identify_ReplyIsNotAV3Identity_SaysRegenerateThePlcCode()
    {
        await using var rig = V3Rig.Start([V3Rig.Handler(2)], "VB100");
        rig.Tamper = (command, reply) => command == Command.Identify
            ? Codec.Encode(new Reply(ReplyStatus.Ok, (ushort)((reply[3] << 8) | reply[4]), [2, .. new byte[23]]))
            : reply;

        var reply = await rig.Bus.IdentifyAsync(Two);

        reply.Failure!.Kind.Should().Be(PlcErrorKind.HandlerOutdated);
        reply.Failure.Message.Should().Contain("regenerate the PLC code").And.Contain("version 2");
    }

    [Fact]
    public async Task Identify_StationRunsAV2Handler_SaysRegenerateThePlcCode()
    {
        var (link, clock) = LinkToAV2Station();
        var plan = PollPlanner.Build([new WatchedItem(Two, PlcAddress.Parse("VB100"))], new Dictionary<Station, CpuProfile> { [Two] = CpuProfiles.For(CpuModel.Cpu224) });
        await using var panel = Bus.StartV3(link, plan, BusSettings.OnDemand, clock);

        var reply = await panel.IdentifyAsync(Two);

        reply.Failure!.Kind.Should().Be(PlcErrorKind.HandlerOutdated);
        reply.Failure.Message.Should().Be("station 2 runs an Operator Panel handler of protocol v2, but the panel speaks protocol v3: regenerate the PLC code (opanel generate) and download it");
    }

    [Fact]
    public async Task Read_StationRunsAV2Handler_SaysRegenerateThePlcCodeOnce()
    {
        var (link, _) = LinkToAV2Station();

        var first = await link.ExchangeAsync(new ReadRequest(Two, [new ReadItem(ProtocolArea.V, 100, 1)]), default);
        var second = await link.ExchangeAsync(new ReadRequest(Two, [new ReadItem(ProtocolArea.V, 100, 1)]), default);

        first.Failure!.Kind.Should().Be(PlcErrorKind.HandlerOutdated, "opanel read and write start with a READ: a v2 station is told to regenerate, not \"no answer\"");
        first.Failure.Message.Should().Be("station 2 runs an Operator Panel handler of protocol v2, but the panel speaks protocol v3: regenerate the PLC code (opanel generate) and download it");
        second.Failure!.Kind.Should().Be(PlcErrorKind.NoAnswer, "the probe runs once per station and link, so an offline station costs its time once");
    }

    [Fact]
    public async Task Stop_FullHandlerWithStop_StationStopsAfterOneStopRequest()
    {
        var station = V3Rig.Handler(2, allowStop: true);
        await using var rig = V3Rig.Start([station], "VB100");

        var outcome = await rig.Bus.StopAsync(Two);

        outcome.Should().BeOfType<StopOutcome.Stopped>();
        station.Mode.Should().Be(OperatingMode.Stop);
        rig.Requests.Should().Equal(Command.Identify, Command.Stop);
    }

    [Fact]
    public async Task Stop_HandlerWithoutStop_NothingSent()
    {
        var station = V3Rig.Handler(2);
        await using var rig = V3Rig.Start([station], "VB100");

        var outcome = await rig.Bus.StopAsync(Two);

        outcome.Should().BeOfType<StopOutcome.NotInHandler>();
        station.Mode.Should().Be(OperatingMode.Run);
        rig.Requests.Should().Equal(Command.Identify);
    }

    [Fact]
    public async Task Refresh_CompactHandlerIdentified_ReadWithReadOnly()
    {
        var station = V3Rig.Handler(2, HandlerShape.Compact);
        (station.Memory.V[100], station.Memory.M[4], station.Memory.M[5]) = (0x42, 0x12, 0x34);
        station.Memory.WriteDoubleWord(ProtocolArea.V, 200, 0x0A0B0C0D);
        await using var rig = V3Rig.Start([station], "VB100", "MW4", "VD200");
        await rig.Bus.IdentifyAsync(Two);

        await rig.Bus.RefreshAsync();

        rig.Value("VB100").Should().Be("42 Good");
        rig.Value("MW4").Should().Be("1234 Good");
        rig.Value("VD200").Should().Be("0A0B0C0D Good");
        rig.Requests.Skip(1).Should().OnlyContain(c => c == Command.Read).And.NotBeEmpty();
    }

    [Fact]
    public async Task Refresh_CompactHandlerNotIdentified_AsksIdentifyOnceThenReadsWithRead()
    {
        var station = V3Rig.Handler(2, HandlerShape.Compact);
        station.Memory.V[100] = 0x42;
        await using var rig = V3Rig.Start([station], "VB100");

        await rig.Bus.RefreshAsync();
        await rig.Bus.RefreshAsync();

        rig.Value("VB100").Should().Be("42 Good");
        rig.Requests.Should().Equal(Command.Identify, Command.Read, Command.Read);
    }

    /// <summary>A v3 link to station 2 running the v2 reference handler, on a simulated line in simulated time.</summary>
    private static (V3Link Link, TimeProvider Clock) LinkToAV2Station()
    {
        var bus = new BusSimulator();
        bus.Attach(new ReferencePlc(new HandlerConfig(Two, CpuProfiles.For(CpuModel.Cpu224))));
        var transport = new SimulatedLineTransport(new ReferenceLine(bus, []));
        var options = LinkOptions.For(new SerialSettings { PortName = "simulated", BaudRate = 9600 }) with { InterFrameGap = TimeSpan.Zero };
        return (new V3Link(transport, options, transport.Clock), transport.Clock);
    }
}

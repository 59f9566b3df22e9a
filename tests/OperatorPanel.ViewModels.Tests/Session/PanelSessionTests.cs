using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.ViewModels.Session;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Session;

public sealed class PanelSessionTests : IAsyncDisposable
{
    private readonly PanelFixture _panel = new();

    [Fact]
    public async Task TriggeredMode_ClockRuns_NothingPolledUntilRefreshNow()
    {
        await _panel.ConnectAsync();
        var afterConnect = _panel.Transport.FramesSent;

        _panel.Clock.Advance(TimeSpan.FromMinutes(5));

        _panel.Transport.FramesSent.Should().Be(afterConnect, "triggered mode polls nothing on its own");

        await _panel.RefreshAsync();

        _panel.Transport.FramesSent.Should().BeGreaterThan(afterConnect);
        var afterRefresh = _panel.Transport.FramesSent;
        _panel.Clock.Advance(TimeSpan.FromMinutes(5));
        _panel.Transport.FramesSent.Should().Be(afterRefresh, "one refresh is one cycle");
    }

    [Fact]
    public async Task StatusBar_RefreshAndWrite_ShowTheLinksCountersAtOnceWithoutATimer()
    {
        await _panel.ConnectAsync();
        var station = _panel.Session.Stations.Single();
        var afterConnect = station.Statistics.Requests;

        await _panel.RefreshAsync();
        var afterRefresh = station.Statistics.Requests;
        await _panel.Session.WriteAsync(WriteRequest.Bytes(PanelFixture.Filler, PlcAddress.Parse("VW10"), [0x00, 0x2A]));

        afterConnect.Should().Be(1, "the IDENTIFY on connecting");
        afterRefresh.Should().BeGreaterThan(afterConnect, "the cycle's READs show when the cycle ends");
        station.Statistics.Requests.Should().Be(afterRefresh + 1, "the write shows when it ends");
        _panel.Clock.Advance(StatusLine.ErrorLifetime);
        _panel.Clock.ActiveTimers.Should().Be(0, "nothing samples the line on a timer (the status message's expiry has run out)");
        station.Statistics.Requests.Should().Be(afterRefresh + 1, "triggered refresh: time passing sends nothing");
    }

    [Fact]
    public async Task Connect_StatusLine_SaysWhichStationsArePolledOnWhichPortsAndIsNoError()
    {
        await _panel.ConnectAsync();

        _panel.Session.StatusLine.Text.Should().Be("Polling Filler on COM7");
        _panel.Session.StatusLine.IsError.Should().BeFalse();
        _panel.Session.Stations[0].HealthText.Should().Be("not read yet", "triggered refresh: nothing is read before F5");
        await _panel.RefreshAsync();
        _panel.Session.Stations[0].HealthText.Should().Be("online");
    }

    [Fact]
    public async Task Values_SubscribedAddress_GetsItsValueAtOnceEveryChangeAndNotReadAfterDisconnect()
    {
        var speed = new List<PolledValue>();
        var recipe = new List<PolledValue>();
        using var speedSubscription = _panel.Session.Values.Subscribe(PanelFixture.Filler, PlcAddress.Parse("VW10"), speed.Add);
        using var recipeSubscription = _panel.Session.Values.Subscribe(PanelFixture.Filler, PlcAddress.Parse("MB4"), recipe.Add);
        await _panel.ConnectAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1234);
        _panel.Plc.Memory.Area(ProtocolArea.M)[4] = 7;
        await _panel.RefreshAsync();
        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 1235);
        await _panel.RefreshAsync();
        await _panel.Session.DisconnectAsync();

        speed[0].Error.Should().Be("not read yet", "a subscriber hears the value as it is when it subscribes");
        speed.Where(v => v.HasValue).Select(v => Convert.ToHexString(v.Raw.AsSpan())).Should().Equal("04D2", "04D3");
        speed[^1].Should().Match<PolledValue>(v => !v.HasValue && v.Quality == ValueQuality.Bad, "a disconnected line has no values");
        recipe.Where(v => v.HasValue).Should().ContainSingle("MB4 did not change after its first read, so it hears no second batch")
            .Which.Raw.Should().Equal(7);
    }

    [Fact]
    public async Task Values_Unsubscribed_HearsNothingMore()
    {
        var speed = new List<PolledValue>();
        await _panel.ConnectAsync();
        var subscription = _panel.Session.Values.Subscribe(PanelFixture.Filler, PlcAddress.Parse("VW10"), speed.Add);
        subscription.Dispose();

        _panel.Plc.Memory.WriteWord(ProtocolArea.V, 10, 99);
        await _panel.RefreshAsync();

        speed.Should().ContainSingle("only the value at subscription time arrived");
    }

    [Fact]
    public async Task Connect_StationAnswers_OnlineAndIdentified()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        var station = _panel.Session.Stations.Should().ContainSingle().Subject;
        station.Health.Should().Be(StationHealth.Online);
        station.Identity.Should().Match<StationIdentity>(i => i.Model == CpuModel.Cpu224 && i.ProtocolVersion == 3 && i.V3 != null && i.ModeSwitchRun);
        station.CpuMismatch.Should().BeFalse();
        station.Statistics.Replies.Should().BeGreaterThanOrEqualTo(2, "IDENTIFY and the refresh were answered");
    }

    [Fact]
    public async Task PortVanishes_StationOfflineWithReasonThenRecovers()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        _panel.Transport.Vanished = true;
        await _panel.RefreshAsync();

        var station = _panel.Session.Stations.Single();
        station.Health.Should().Be(StationHealth.Offline);
        station.HealthText.Should().Contain("PortUnavailable").And.Contain("COM7");
        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("VW10"), out var stale).Should().BeTrue();
        stale.Quality.Should().Be(ValueQuality.Stale);

        // The cable is plugged back in a while later: the link reopens the port at most every ReopenInterval.
        _panel.Transport.Vanished = false;
        _panel.Clock.Advance(ReconnectOptions.Default.ReopenInterval);
        await _panel.RefreshAsync();

        station.Health.Should().Be(StationHealth.Online);
        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("VW10"), out var good).Should().BeTrue();
        good.Quality.Should().Be(ValueQuality.Good);
    }

    [Fact]
    public async Task PlcSwitchedToStop_AnsweredBefore_ShownAsStopped()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        _panel.Plc.Mode = OperatingMode.Stop;
        await _panel.RefreshAsync();

        var station = _panel.Session.Stations.Single();
        station.Health.Should().Be(StationHealth.Stopped);
        station.HealthText.Should().Contain("STOP");
    }

    [Fact]
    public async Task Identify_PlcHasAnotherCpu_MismatchFlaggedInStatusLine()
    {
        _panel.Connector.Configure(new HandlerConfig(PanelFixture.Filler, CpuProfiles.For(CpuModel.Cpu226)));

        await _panel.ConnectAsync();

        var station = _panel.Session.Stations.Single();
        station.CpuMismatch.Should().BeTrue();
        station.Identity!.CpuText.Should().Be("CPU 226");
        _panel.Session.StatusLine.IsError.Should().BeTrue();
        _panel.Session.StatusLine.Text.Should().Be("Filler: the PLC reports CPU 226, the project says CPU 224");
    }

    [Fact]
    public async Task Identify_ReplyNotProtocolV3_ToldToRegenerateThePlcCode()
    {
        await _panel.ConnectAsync();
        _panel.Transport.RewriteReply = reply => RewriteIdentifyVersion(reply, 0x02);

        await _panel.Session.IdentifyAsync().Guarded();
        _panel.Transport.RewriteReply = null;
        await _panel.RefreshAsync();

        var station = _panel.Session.Stations.Single();
        station.IdentifyError.Should().StartWith("IDENTIFY: HandlerOutdated: station 2 runs a handler whose IDENTIFY reply is not protocol v3's")
            .And.EndWith("regenerate the PLC code (opanel generate) and download it");
    }

    [Fact]
    public async Task Disconnect_Connected_StationsUnknownAndValuesGone()
    {
        await _panel.ConnectAsync();
        await _panel.RefreshAsync();

        await _panel.Session.DisconnectAsync().Guarded();

        _panel.Session.IsConnected.Should().BeFalse();
        _panel.Session.Stations.Single().Health.Should().Be(StationHealth.Unknown);
        _panel.Session.Values.TryGetValue(PanelFixture.Filler, PlcAddress.Parse("VW10"), out _).Should().BeFalse();
    }

    public async ValueTask DisposeAsync() => await _panel.DisposeAsync();

    /// <summary>An IDENTIFY reply (STATUS 80 with the 24 identity bytes) with another PROTOCOL_VERSION, its check made good again.</summary>
    private static byte[] RewriteIdentifyVersion(byte[] reply, byte version)
    {
        Core.Protocol.V3.Codec.TryDecodeReply(reply, out var decoded, out _).Should().BeTrue();
        return decoded.Payload.Length == Core.Protocol.V3.Identity.PayloadBytes
            ? Core.Protocol.V3.Codec.Encode(decoded with { Payload = decoded.Payload.SetItem(0, version) })
            : reply;
    }
}

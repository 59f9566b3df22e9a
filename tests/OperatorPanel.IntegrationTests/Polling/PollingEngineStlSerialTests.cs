using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl.Freeport;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.IntegrationTests.Polling;

/// <summary>
/// The whole path of issue 4 over a socat pty: PollingEngine -> PlcLink -> SerialPortTransport -> pty -> SimulatedPlcHost
/// running the .awl StlGen generates in the STL interpreter. Real time, each wait bounded by <see cref="SerialLineRig.Limit"/>.
/// </summary>
public sealed class PollingEngineStlSerialTests
{
    private const int Baud = 19200;
    private static readonly CpuProfile Cpu = CpuProfiles.For(CpuModel.Cpu226);

    [Fact]
    public async Task Refresh_GeneratedHandler_ReturnsThePlcBytes()
    {
        var (line, station) = Line(2);
        (station.Memory.V[100], station.Memory.V[101], station.Memory.M[3], station.Memory.Q[15]) = (0xBE, 0xEF, 0x42, 0x5A);
        await using var rig = await SerialLineRig.StartAsync(line, [(new Station(2), Cpu)], ["VW100", "MB3", "QB15"], Baud);

        var result = await rig.RefreshUntilAsync(r => r.FramesFailed == 0);

        result.FramesFailed.Should().Be(0);
        rig.Value(new Station(2), "VW100").Raw.Should().Equal(0xBE, 0xEF);
        rig.Value(new Station(2), "MB3").Raw.Should().Equal(0x42);
        rig.Value(new Station(2), "QB15").Raw.Should().Equal(0x5A);
    }

    [Fact]
    public async Task Write_GeneratedHandler_ConfirmedByReadBackAndHeldInMemory()
    {
        var (line, station) = Line(2);
        await using var rig = await SerialLineRig.StartAsync(line, [(new Station(2), Cpu)], ["VW200", "QB1"], Baud);

        var word = await rig.Bus.WriteAsync(WriteRequest.Bytes(new Station(2), PlcAddress.Parse("VW200"), [0x01, 0x2C])).WaitAsync(SerialLineRig.Limit);
        var output = await rig.Bus.WriteAsync(WriteRequest.Bytes(new Station(2), PlcAddress.Parse("QB1"), [0x5A])).WaitAsync(SerialLineRig.Limit);

        ConfirmedWrite.ReadBackOf(word).Should().Equal(0x01, 0x2C);
        ConfirmedWrite.ReadBackOf(output).Should().Equal(0x5A);
        station.Memory.ReadWord(ProtocolArea.V, 200).Should().Be(300);
        station.Memory.Q[1].Should().Be(0x5A);
    }

    [Fact]
    public async Task Refresh_StationInTerm_GoesSilentWhileTheOtherAnswers()
    {
        var (line, station) = Line(2, 3);
        await using var rig = await SerialLineRig.StartAsync(line, [(new Station(2), Cpu), (new Station(3), Cpu)], ["VB0"], Baud);
        await rig.RefreshUntilAsync(_ => rig.State(new Station(2)) == StationState.Online && rig.State(new Station(3)) == StationState.Online);

        station.Plc.ModeSwitch = ModeSwitch.Term;
        await rig.RefreshUntilAsync(_ => rig.State(new Station(2)) == StationState.Offline);

        rig.State(new Station(2)).Should().Be(StationState.Offline);
        rig.State(new Station(3)).Should().Be(StationState.Online);
    }

    [Fact]
    public async Task Refresh_GeneratedHandlerWithTwoLists_ChangesArriveThroughOne09()
    {
        var (line, station) = Line(2);
        string[] watched = [.. Enumerable.Range(0, 26).Select(i => $"VB{i * 10}")];
        await using var rig = await SerialLineRig.StartAsync(line, [(new Station(2), Cpu)], watched, Baud);
        var identity = await rig.Bus.IdentifyAsync(new Station(2), CancellationToken.None).WaitAsync(SerialLineRig.Limit);
        identity.Response.Should().BeOfType<IdentifyResponse>();
        await rig.RefreshUntilAsync(r => r.FramesFailed == 0);
        (station.Memory.V[0], station.Memory.V[250]) = (0x11, 0x5A);
        var before = rig.Tap.Received.Length;

        var result = await rig.RefreshAsync();

        result.FramesFailed.Should().Be(0);
        rig.Bus.Plan.ListCount.Should().Be(2);
        System.Text.RegularExpressions.Regex.Matches(rig.Tap.Received[before..], "<[^<>]*>").Select(m => m.Value[5..7])
            .Should().Equal(["09"], "the handler's IDENTIFY has FEATURES bit 2, so both lists in step go in one 09");
        rig.Value(new Station(2), "VB0").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x11);
        rig.Value(new Station(2), "VB250").Should().Match<PolledValue>(v => v.Quality == ValueQuality.Good && v.Raw[0] == 0x5A);
    }

    /// <summary>Stations with the generated handler on one line; the first is returned for memory access.</summary>
    private static (StlLine Line, StlStation First) Line(params int[] stations)
    {
        var settings = new LineSettings(Baud, Core.Transport.Parity.None, 8);
        var line = new StlLine(settings);
        foreach (var address in stations)
        {
            var generated = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = Cpu, Station = address, BaudRate = Baud });
            generated.Ok.Should().BeTrue(string.Join("; ", generated.Diagnostics));
            StlStation.TryCreate(generated.AwlText, Cpu, 0, settings, out var station, out var error).Should().BeTrue(error);
            line.Attach(station!, runProcess: false);
        }

        return (line, line.Stations[0]);
    }
}

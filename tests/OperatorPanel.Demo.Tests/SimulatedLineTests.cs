using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Transport;
using OperatorPanel.Simulator.Hosting;
using OperatorPanel.Simulator.Reference;

namespace OperatorPanel.Demo.Tests;

/// <summary>--model picks what answers; the STL model is the generated handler in the interpreter (--demo and simulate).</summary>
public sealed class SimulatedLineTests
{
    private static readonly CpuProfile Cpu226 = CpuProfiles.For(CpuModel.Cpu226);

    [Theory]
    [InlineData("Stl", typeof(StlLine))]
    [InlineData("Reference", typeof(V3ReferenceLine))]
    public void TryCreate_Model_ChoosesTheLine(string model, Type expected)
    {
        SimulatedLine.TryCreate([new HandlerConfig(new Station(2), Cpu226, port: 1)], Enum.Parse<SimulationModel>(model), Serial(19200), runProcess: true, out var line, out var error)
            .Should().BeTrue(error);

        line!.Line.Should().BeOfType(expected);
        line.RunsProcess.Should().BeTrue();
    }

    [Fact]
    public void TryCreate_StlTwoStations_EachRunsItsGeneratedHandler()
    {
        SimulatedLine.TryCreate(
            [new HandlerConfig(new Station(3), Cpu226), new HandlerConfig(new Station(4), Cpu226, replyDelayMs: 9)],
            SimulationModel.Stl, Serial(19200), runProcess: false, out var line, out var error).Should().BeTrue(error);

        var stations = line!.Line.Should().BeOfType<StlLine>().Subject.Stations;
        stations.Should().HaveCount(2);
        line.WarmUp(TimeSpan.FromMilliseconds(20));
        stations.Should().OnlyContain(s => s.Port.IsFreeport && s.Port.Line.Baud == 19200 && s.Port.IsReceiving);
    }

    [Theory]
    [InlineData(true, OperatingMode.Stop)]
    [InlineData(false, OperatingMode.Run)]
    public void TryCreate_StlHandlerWithStopAsConfigured_GoesToStopOnlyWhenGeneratedWithIt(bool allowStop, OperatingMode expected)
    {
        SimulatedLine.TryCreate([new HandlerConfig(new Station(2), Cpu226, allowStop: allowStop)], SimulationModel.Stl, Serial(9600), runProcess: true, out var line, out var error)
            .Should().BeTrue(error);
        line!.WarmUp(TimeSpan.FromMilliseconds(50));

        var stop = Codec.Encode(Request.Stop(new Station(2), 1));
        line.Line.Deliver(stop);
        line.WarmUp(TimeSpan.FromMilliseconds(200));

        Codec.TryDecodeReplyTo(line.Line.TakeTransmitted(), stop, out var reply, out var error2).Should().BeTrue(error2.ToString());
        reply.Status.Should().Be(allowStop ? ReplyStatus.Ok : ReplyStatus.UnknownCommand, "80 with STOP generated, 85 (unknown command) without");
        line.Line.Should().BeOfType<StlLine>().Which.Stations[0].Mode.Should().Be(expected);
    }

    [Fact]
    public void TryCreate_ProtocolTwoStation_RunsTheV2HandlerForTheRegenerateMessage()
    {
        SimulatedLine.TryCreate([new HandlerConfig(new Station(2), Cpu226) { Protocol = 2 }], SimulationModel.Stl, Serial(9600), runProcess: false, out var line, out var error)
            .Should().BeTrue(error);
        line!.WarmUp(TimeSpan.FromMilliseconds(50));

        line.Line.Deliver(RequestCodec.Encode(new IdentifyRequest(new Station(2), 1)));
        line.WarmUp(TimeSpan.FromMilliseconds(300));

        var reply = System.Text.Encoding.ASCII.GetString(line.Line.TakeTransmitted());
        reply.Should().StartWith("<02018100", "a v2 reply in hex characters: station 02, SEQ 01, CMD 01 with bit 7, STATUS 00").And.EndWith(">");
        line.Line.FramesReceived.Should().Be(1, "a v2 line counts frames by '>'");
    }

    [Fact]
    public void TryCreate_BaudTheCpuCannotSet_FailsNamingTheDiagnostic()
    {
        var early = CpuProfiles.For(CpuModel.Cpu224, CpuRevision.Early);

        SimulatedLine.TryCreate([new HandlerConfig(new Station(2), early)], SimulationModel.Stl, Serial(115200), runProcess: false, out var line, out var error)
            .Should().BeFalse();

        line.Should().BeNull();
        error.Should().StartWith("station 2: the handler cannot be generated: STL").And.Contain("115200");
    }

    private static SerialSettings Serial(int baud) => new() { PortName = "test", BaudRate = baud };
}

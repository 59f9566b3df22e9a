using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// 07 STOP of the generated handler in the STL interpreter against the reference model: with STOP generated the whole
/// reply goes out first, then the CPU is in STOP and silent (the port is PPI again: a READ gets no answer); without it 07 is an unknown
/// command (05) and the CPU keeps running; a wrong payload or length is refused and the CPU keeps running.
/// </summary>
public sealed class StopDifferentialTests
{
    [Fact]
    public void Stop_Enabled_RepliesThenTheCpuIsInStopAndSilent()
    {
        var (harness, panel) = Station(allowStop: true);

        var reply = panel.Send(new StopRequest(panel.Station, panel.NextSequence()));
        var afterwards = panel.Send(Read(panel));
        var mode = harness.Mode;

        reply.Should().BeOfType<StopResponse>("the reply leaves before the CPU stops");
        mode.Should().Be(OperatingMode.Stop);
        harness.Reference.Mode.Should().Be(OperatingMode.Stop);
        afterwards.Should().BeNull("in STOP the port is PPI: no Freeport answer");
    }

    [Fact]
    public void Stop_NotGenerated_AnswersUnknownCommandAndKeepsRunning()
    {
        var (harness, panel) = Station(allowStop: false);

        var error = panel.Error(new StopRequest(panel.Station, panel.NextSequence()));
        var read = panel.Send(Read(panel));

        error.Should().Be(ProtocolError.UnknownCommand);
        harness.Mode.Should().Be(OperatingMode.Run);
        read.Should().BeOfType<ReadResponse>("the handler still answers");
    }

    [Theory]
    [InlineData("STOQ", "8706")]
    [InlineData("stop", "8706")]
    [InlineData("STO", "8704")]
    [InlineData("STOP!", "8704")]
    public void Stop_WrongPayload_IsRefusedAndTheCpuKeepsRunning(string payload, string cmdAndStatus)
    {
        var (harness, panel) = Station(allowStop: true);

        var (stl, reference) = panel.Raw(new FreeportFrame(2, panel.NextSequence(), (byte)CommandCode.Stop, [.. payload.Select(c => (byte)c)]));
        var read = panel.Send(Read(panel));

        stl.Should().Be(reference);
        stl.Substring(5, 4).Should().Be(cmdAndStatus);
        harness.Mode.Should().Be(OperatingMode.Run);
        read.Should().BeOfType<ReadResponse>("the handler still answers");
    }

    private static ReadRequest Read(ChangesExchange panel) => new(panel.Station, panel.NextSequence(), [new ReadItem(ProtocolArea.V, 100, 2)]);

    private static (DifferentialHarness Harness, ChangesExchange Panel) Station(bool allowStop)
    {
        var options = new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu226), Station = 2, AllowStop = allowStop };
        var harness = new DifferentialHarness(options, new Random(7));
        return (harness, new ChangesExchange(harness, 2));
    }
}

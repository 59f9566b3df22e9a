using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Soak;
using OperatorPanel.TestKit;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class SoakFieldTests
{
    private readonly PlcMemory _memory = new(CpuProfiles.For(CpuModel.Cpu226));
    private readonly ManualTimeProvider _time = new();

    [Fact]
    public void RunUntil_PastTwoPeriods_SetsItsBytesTwiceFromThePatternOfEachStep()
    {
        var inputs = new byte[16];
        var field = new SoakField(new ScriptedLine(_memory), inputs, _memory, [new WatchedBytes(ProtocolArea.I, 14, 2)], _time);

        field.RunUntil(SoakField.Period * 2.5);

        field.Settings.Should().HaveCount(2);
        field.Settings[1].Before.Should().Equal(SoakField.Pattern(1, 14), SoakField.Pattern(1, 15));
        field.Settings[1].After.Should().Equal(SoakField.Pattern(2, 14), SoakField.Pattern(2, 15));
        inputs[14..].Should().Equal(SoakField.Pattern(2, 14), SoakField.Pattern(2, 15));
        _memory.I.Should().AllBeEquivalentTo((byte)0, "the CPU copies its inputs into I, not the field");
    }

    [Fact]
    public void Pattern_NeighbouringBytesAndSteps_Differ()
    {
        SoakField.Pattern(1, 15).Should().NotBe(SoakField.Pattern(1, 14)).And.NotBe(SoakField.Pattern(2, 15));
    }

    [Fact]
    public void New_RangeInQ_IsRefused()
    {
        var act = () => new SoakField(new ScriptedLine(_memory), new byte[16], _memory, [new WatchedBytes(ProtocolArea.Q, 0, 1)], _time);

        act.Should().Throw<ArgumentException>().WithMessage("*the field sets only I and SM*");
    }
}

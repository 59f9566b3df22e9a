using System.Collections.Immutable;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Soak;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class SoakJudgeTests
{
    private static readonly SoakRegion Region = new(1000, 2);
    private static readonly WriteOutcome Confirmed = new WriteOutcome.Confirmed([]);
    private static readonly WriteOutcome Unknown = new WriteOutcome.Unknown(default, "no reply", "the read-back failed too");
    private static readonly WriteOutcome NotApplied = new WriteOutcome.NotApplied([0, 0, 0, 0], "no reply");

    [Fact]
    public void Judge_ConfirmedWriteExecutedAtItsAddress_IsNoFalseConfirmation()
    {
        var writes = new[] { new SoakWrite(1, 1004, 0x11223344, Confirmed) };

        var result = Judge(writes, [], [Change(10, 1004, [0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44])]);

        result.WritesConfirmed.Should().Be(1);
        result.FalseConfirmations.Should().Be(0);
        result.ExecutedNeverSent.Should().Be(0);
    }

    [Fact]
    public void Judge_ConfirmedWriteExecutedOneByteFurther_IsAFalseConfirmationAndAWriteNeverSent()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x11223344, Confirmed) };

        var result = Judge(writes, [], [Change(10, 1001, [0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44])]);

        result.FalseConfirmations.Should().Be(1);
        result.ExecutedNeverSent.Should().Be(1);
        result.Findings.Should().Equal(
            "V bytes 1001-1004 changed 00000000 -> 11223344: no panel write explains it",
            "write 1 VD1000 := 16#11223344 reported confirmed, not executed as sent");
    }

    [Fact]
    public void Judge_ConfirmedWriteThatAlsoChangedTheNextBytes_IsAFalseConfirmation()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x11223344, Confirmed) };

        var result = Judge(writes, [], [Change(10, 1000, [0, 0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44, 0x55])]);

        result.FalseConfirmations.Should().Be(1);
    }

    [Fact]
    public void Judge_ConfirmedWriteThePlcNeverExecuted_IsAFalseConfirmation()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x11223344, Confirmed) };

        var result = Judge(writes, [], []);

        result.FalseConfirmations.Should().Be(1);
    }

    [Fact]
    public void Judge_SecondWriteExecutedBeforeTheFirst_CountsOneOutOfOrder()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x01010101, Unknown), new SoakWrite(2, 1004, 0x02020202, Confirmed) };

        var result = Judge(writes, [], [Change(10, 1004, [0, 0, 0, 0], [2, 2, 2, 2]), Change(20, 1000, [0, 0, 0, 0], [1, 1, 1, 1])]);

        result.WritesOutOfOrder.Should().Be(1);
        result.NotConfirmedButExecuted.Should().Be(1);
        result.WritesNotConfirmed.Should().Equal(new Dictionary<string, int> { ["unknown"] = 1 });
        result.FalseNotApplied.Should().Be(0);
    }

    [Fact]
    public void Judge_WriteReportedNotAppliedThatThePlcExecuted_IsAFalseNotApplied()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x01010101, NotApplied) };

        var result = Judge(writes, [], [Change(10, 1000, [0, 0, 0, 0], [1, 1, 1, 1])]);

        result.FalseNotApplied.Should().Be(1);
        result.FalseConfirmations.Should().Be(0);
    }

    [Fact]
    public void Judge_ValueHeldDuringTheStep_IsRight_ValueOverwrittenBeforeTheStep_IsWrong()
    {
        var writes = new[] { new SoakWrite(1, 1000, 0x01010101, Confirmed), new SoakWrite(2, 1000, 0x02020202, Confirmed) };
        var changes = new[] { Change(10, 1000, [0, 0, 0, 0], [1, 1, 1, 1]), Change(20, 1000, [1, 1, 1, 1], [2, 2, 2, 2]) };

        var held = Judge(writes, [new ShownValue(1000, 0x01010101, 15, 30)], changes);
        var overwritten = Judge(writes, [new ShownValue(1000, 0x01010101, 25, 30)], changes);
        var otherAddress = Judge(writes, [new ShownValue(1004, 0x02020202, 25, 30)], changes);

        held.WrongValuesShownGood.Should().Be(0);
        overwritten.WrongValuesShownGood.Should().Be(1);
        otherAddress.WrongValuesShownGood.Should().Be(1);
    }

    [Fact]
    public void Judge_InitialValueBeforeAnyWrite_IsRight()
    {
        var result = Judge([], [new ShownValue(1004, 0, 1, 5)], []);

        result.ValuesShownGood.Should().Be(1);
        result.WrongValuesShownGood.Should().Be(0);
    }

    [Fact]
    public void Judge_ChangeOutsideTheRegion_IsAWriteNeverSent()
    {
        var result = Judge([], [], [new MemoryChange(5, ProtocolArea.M, 3, [0], [8])]);

        result.ExecutedNeverSent.Should().Be(1);
    }

    private static SoakJudgement Judge(IReadOnlyList<SoakWrite> writes, IReadOnlyList<ShownValue> shown, IReadOnlyList<MemoryChange> changes) =>
        new SoakJudge(Region, new byte[Region.Bytes]).Judge(writes, shown, changes);

    private static MemoryChange Change(long at, int first, byte[] before, byte[] after) =>
        new(at, ProtocolArea.V, first, [.. before], ImmutableArray.Create(after));
}

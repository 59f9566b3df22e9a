using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Protocol.V3;
using OperatorPanel.Core.Writes;
using OperatorPanel.Simulator.Soak;

namespace OperatorPanel.Simulator.Tests.Soak;

public sealed class SoakJudgeTests
{
    private static readonly SoakRegion Region = new(
        [.. new[] { "VD1000", "VD1004", "QW14", "QB15", "Q15.7", "MW30", "MB31", "IB15", "I15.0", "SMW548" }.Select(PlcAddress.Parse)]);

    private static readonly WriteOutcome Confirmed = new WriteOutcome.Confirmed([]);
    private static readonly WriteOutcome Unknown = new WriteOutcome.Unknown(default, "no reply", "the read-back failed too");
    private static readonly WriteOutcome NotApplied = new WriteOutcome.NotApplied([0, 0, 0, 0], "no reply");

    [Fact]
    public void Judge_ConfirmedWriteExecutedAtItsAddress_IsNoFalseConfirmation()
    {
        var writes = new[] { Write(1, "VD1004", [0x11, 0x22, 0x33, 0x44], Confirmed) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.V, 1004, [0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44])]);

        result.WritesConfirmed.Should().Be(1);
        result.FalseConfirmations.Should().Be(0);
        result.ExecutedNeverSent.Should().Be(0);
        result.ConfirmedByItem.Should().Equal(new Dictionary<string, int> { ["VD1004"] = 1 });
    }

    [Fact]
    public void Judge_ConfirmedWriteExecutedOneByteFurther_IsAFalseConfirmationAndAChangeNothingExplains()
    {
        var writes = new[] { Write(1, "VD1000", [0x11, 0x22, 0x33, 0x44], Confirmed) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.V, 1001, [0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44])]);

        result.FalseConfirmations.Should().Be(1);
        result.ExecutedNeverSent.Should().Be(1);
        result.Findings.Should().Equal(
            "V bytes 1001-1004 changed 00000000 -> 11223344: no panel write explains it",
            "write 1 VD1000 := 16#11223344 reported confirmed, not executed as sent");
    }

    [Fact]
    public void Judge_ConfirmedWriteThatAlsoChangedTheNextBytes_IsAFalseConfirmation()
    {
        var writes = new[] { Write(1, "VD1000", [0x11, 0x22, 0x33, 0x44], Confirmed) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.V, 1000, [0, 0, 0, 0, 0], [0x11, 0x22, 0x33, 0x44, 0x55])]);

        result.FalseConfirmations.Should().Be(1);
    }

    [Fact]
    public void Judge_ConfirmedWriteThePlcNeverExecuted_IsAFalseConfirmation()
    {
        var writes = new[] { Write(1, "VD1000", [0x11, 0x22, 0x33, 0x44], Confirmed) };

        var result = Judge(writes, [], []);

        result.FalseConfirmations.Should().Be(1);
    }

    [Fact]
    public void Judge_SecondWriteExecutedBeforeTheFirst_CountsOneOutOfOrder()
    {
        var writes = new[] { Write(1, "VD1000", [1, 1, 1, 1], Unknown, sent: 0), Write(2, "VD1004", [2, 2, 2, 2], Confirmed, sent: 5) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.V, 1004, [0, 0, 0, 0], [2, 2, 2, 2]), Change(20, ProtocolArea.V, 1000, [0, 0, 0, 0], [1, 1, 1, 1])]);

        result.WritesOutOfOrder.Should().Be(1);
        result.NotConfirmedButExecuted.Should().Be(1);
        result.WritesNotConfirmed.Should().Equal(new Dictionary<string, int> { ["unknown"] = 1 });
        result.FalseNotApplied.Should().Be(0);
    }

    [Fact]
    public void Judge_WordAtTheAreaEndExecutedAfterALaterByteWriteInsideIt_CountsOneOutOfOrder()
    {
        var writes = new[] { Write(1, "MW30", [0x12, 0x34], Unknown, sent: 0), Write(2, "MB31", [0x56], Confirmed, sent: 5) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.M, 31, [0], [0x56]), Change(20, ProtocolArea.M, 30, [0, 0x56], [0x12, 0x34])]);

        result.WritesOutOfOrder.Should().Be(1);
        result.FalseConfirmations.Should().Be(0);
        result.Findings.Should().Equal("write 1 (MW30) executed after write 2");
    }

    [Fact]
    public void Judge_WriteReportedNotAppliedThatThePlcExecuted_IsAFalseNotApplied()
    {
        var writes = new[] { Write(1, "VD1000", [1, 1, 1, 1], NotApplied) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.V, 1000, [0, 0, 0, 0], [1, 1, 1, 1])]);

        result.FalseNotApplied.Should().Be(1);
        result.FalseConfirmations.Should().Be(0);
    }

    [Fact]
    public void Judge_BitWriteThatChangedItsBitAlone_IsExecutedAndNoFalseConfirmation()
    {
        var writes = new[] { Write(1, "Q15.7", [1], Confirmed) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.Q, 15, [0x01], [0x81])]);

        result.FalseConfirmations.Should().Be(0);
        result.ExecutedNeverSent.Should().Be(0);
    }

    [Fact]
    public void Judge_BitWriteConfirmedWhileAnotherBitOfItsByteChanged_IsAFalseConfirmationAndAChangeNothingExplains()
    {
        var writes = new[] { Write(1, "Q15.7", [1], Confirmed) };

        var result = Judge(writes, [], [Change(10, ProtocolArea.Q, 15, [0x00], [0x81])]);

        result.FalseConfirmations.Should().Be(1);
        result.ExecutedNeverSent.Should().Be(1);
    }

    /// <summary>
    /// WRITE BITS stores its byte once (XORB, since 2026-11-28): a 1 written over a 1 is no change at all. A byte seen
    /// cleared and set again is two stores, and the cleared one, a 0 no write carried, is a change nothing explains; the
    /// judge once took the pair for the write in flight, which the AND-then-OR handler made.
    /// </summary>
    [Fact]
    public void Judge_BitWriteOfAOneOverAOneSeenClearedAndSetAgain_CountsTheClearingAsAChangeNothingExplains()
    {
        var writes = new[] { Write(1, "MB31", [0x80], Confirmed, sent: 0), Write(2, "M31.7", [1], Confirmed, sent: 10) };
        var changes = new[] { Change(2, ProtocolArea.M, 31, [0x00], [0x80]), Change(12, ProtocolArea.M, 31, [0x80], [0x00]), Change(13, ProtocolArea.M, 31, [0x00], [0x80]) };

        var result = Judge(writes, [], changes);

        result.ExecutedNeverSent.Should().Be(1);
        result.Findings.Should().Equal("M bytes 31-31 changed 80 -> 00: no panel write explains it");
        result.WritesOutOfOrder.Should().Be(0);
        result.FalseConfirmations.Should().Be(0, "the setting again is write 2's bit alone, to its value");
    }

    /// <summary>The one store of a WRITE BITS that changes its bit is one change, named for that write.</summary>
    [Fact]
    public void Judge_BitWriteStoredOnce_IsAttributedToThatWrite()
    {
        var writes = new[] { Write(1, "MB31", [0x01], Confirmed, sent: 0), Write(2, "M31.7", [1], Unknown, sent: 10) };
        var changes = new[] { Change(2, ProtocolArea.M, 31, [0x00], [0x01]), Change(12, ProtocolArea.M, 31, [0x01], [0x81]) };

        var result = Judge(writes, [], changes);

        result.ExecutedNeverSent.Should().Be(0);
        result.NotConfirmedButExecuted.Should().Be(1, "write 2, reported unknown, made the second change");
        result.WritesOutOfOrder.Should().Be(0);
        result.FalseConfirmations.Should().Be(0);
        result.Findings.Should().BeEmpty();
    }

    /// <summary>The one store of a 1 over a 1 leaves nothing to see: the write is confirmed with the value already there.</summary>
    [Fact]
    public void Judge_BitWriteOfAOneOverAOneStoredOnce_IsConfirmedWithTheValueAlreadyThere()
    {
        var writes = new[] { Write(1, "MB31", [0x80], Confirmed, sent: 0), Write(2, "M31.7", [1], Confirmed, sent: 10) };

        var result = Judge(writes, [], [Change(2, ProtocolArea.M, 31, [0x00], [0x80])]);

        result.ExecutedNeverSent.Should().Be(0);
        result.FalseConfirmations.Should().Be(0);
        result.ConfirmedAlreadyHeld.Should().Be(1);
        result.Findings.Should().BeEmpty();
    }

    /// <summary>
    /// The pair that made the judge tolerate two stores ("write 43 (M31.7) executed after write 55" on a clean line):
    /// with one store per WRITE BITS, a 0 that an earlier bit write carried is that write executed late.
    /// </summary>
    [Fact]
    public void Judge_BitClearedAndSetAgainWhileAnEarlierWriteOfZeroToItWasSent_IsThatWriteOutOfOrder()
    {
        var writes = new[] { Write(1, "M31.7", [0], Confirmed, sent: 0), Write(2, "MB31", [0x80], Confirmed, sent: 10), Write(3, "M31.7", [1], Confirmed, sent: 20) };
        var changes = new[] { Change(12, ProtocolArea.M, 31, [0x00], [0x80]), Change(22, ProtocolArea.M, 31, [0x80], [0x00]), Change(23, ProtocolArea.M, 31, [0x00], [0x80]) };

        var result = Judge(writes, [], changes);

        result.WritesOutOfOrder.Should().Be(1);
        result.Findings.Should().Equal("write 1 (M31.7) executed after write 2");
        result.ExecutedNeverSent.Should().Be(0);
        result.FalseConfirmations.Should().Be(0);
    }

    /// <summary>A byte value recurs: with the value already there the PLC's execution leaves nothing to see, and the PLC holds what the panel says.</summary>
    [Fact]
    public void Judge_ByteWriteConfirmedWhileItsAddressHeldTheValueThroughout_IsCountedAlreadyHeldNotFalse()
    {
        var writes = new[] { Write(1, "QB15", [0], Confirmed) };

        var result = Judge(writes, [], []);

        result.FalseConfirmations.Should().Be(0);
        result.ConfirmedAlreadyHeld.Should().Be(1);
    }

    [Fact]
    public void Judge_ByteWriteConfirmedButNeverExecutedWhileItsAddressHeldAnotherValue_IsAFalseConfirmation()
    {
        var writes = new[] { Write(1, "QB15", [7], Confirmed) };

        var result = Judge(writes, [], []);

        result.FalseConfirmations.Should().Be(1);
        result.ConfirmedAlreadyHeld.Should().Be(0);
    }

    [Fact]
    public void Judge_ValueHeldDuringTheStep_IsRight_ValueOverwrittenBeforeTheStep_IsWrong()
    {
        var writes = new[] { Write(1, "VD1000", [1, 1, 1, 1], Confirmed, sent: 5), Write(2, "VD1000", [2, 2, 2, 2], Confirmed, sent: 15) };
        var changes = new[] { Change(10, ProtocolArea.V, 1000, [0, 0, 0, 0], [1, 1, 1, 1]), Change(20, ProtocolArea.V, 1000, [1, 1, 1, 1], [2, 2, 2, 2]) };

        var held = Judge(writes, [Shown("VD1000", [1, 1, 1, 1], 15, 30)], changes);
        var overwritten = Judge(writes, [Shown("VD1000", [1, 1, 1, 1], 25, 30)], changes);
        var otherAddress = Judge(writes, [Shown("VD1004", [2, 2, 2, 2], 25, 30)], changes);

        held.WrongValuesShownGood.Should().Be(0);
        overwritten.WrongValuesShownGood.Should().Be(1);
        otherAddress.WrongValuesShownGood.Should().Be(1);
    }

    [Fact]
    public void Judge_InitialValueBeforeAnyWrite_IsRight()
    {
        var result = Judge([], [Shown("VD1004", [0, 0, 0, 0], 1, 5)], []);

        result.ValuesShownGood.Should().Be(1);
        result.WrongValuesShownGood.Should().Be(0);
        result.ShownGoodByItem.Should().Equal(new Dictionary<string, int> { ["VD1004"] = 1 });
    }

    /// <summary>
    /// The defect that escaped the soak of VD1000/VD1004 alone, replayed through a real list: MD20 and the 3-byte range
    /// MB29-MB31 share a frame; the range is widened backward to the window MB28-MB31 and its bytes start one byte into
    /// that item (ListPlan.Places). Before ae2df54 the panel took a frame's bytes in one run from its first range's
    /// place, so MB29-MB31 came out of MB28-MB30 and MW30 was shown good with MB29-MB30.
    /// </summary>
    [Fact]
    public void Judge_WordAtTheEndOfMShownFromTheWidenedWindowOneByteEarly_IsAWrongValueShownGood()
    {
        var memory = new byte[32];
        byte[] window = [0x11, 0x22, 0x33, 0x44];
        window.CopyTo(memory, 28);
        ListPlan.TryMake(
            [new ReadItem(ProtocolArea.M, 20, 4), new ReadItem(ProtocolArea.M, 29, 3)], HandlerShape.Full, _ => 32, out var plan).Should().BeTrue();
        var data = plan.Items.SelectMany(i => i.Area == ProtocolArea.M ? memory.Skip(i.Offset).Take(i.Length) : [0]).ToArray();
        var rightRange = data.AsSpan(plan.Places[1], 3).ToArray();
        var defectiveRange = data.AsSpan(plan.Places[0], 7)[4..].ToArray();
        var region = new SoakRegion([PlcAddress.Parse("MW30")]);
        var judge = new SoakJudge(region, new MemoryImage([(new WatchedBytes(ProtocolArea.M, 0, 32), memory)]));

        var right = judge.Judge([], [Shown("MW30", rightRange[1..], 1, 5)], [], []);
        var defective = judge.Judge([], [Shown("MW30", defectiveRange[1..], 1, 5)], [], []);

        plan.Items[1].Should().Be(new ReadItem(ProtocolArea.M, 28, 4));
        rightRange.Should().Equal(0x22, 0x33, 0x44);
        defectiveRange.Should().Equal(0x11, 0x22, 0x33);
        right.WrongValuesShownGood.Should().Be(0);
        defective.WrongValuesShownGood.Should().Be(1);
        defective.Findings.Should().Equal("MW30 shown as good 16#2233, which it did not hold then");
    }

    [Fact]
    public void Judge_InputChangeTheFieldMade_IsExplainedAndItsValueShownIsRight()
    {
        var setting = Change(5, ProtocolArea.I, 12, [0, 0, 0, 0], [1, 2, 3, 4]);

        var result = Judge([], [Shown("IB15", [4], 12, 20), Shown("I15.0", [0], 12, 20)], [Change(10, ProtocolArea.I, 12, [0, 0, 0, 0], [1, 2, 3, 4])], [setting]);

        result.FieldChanges.Should().Be(1);
        result.ExecutedNeverSent.Should().Be(0);
        result.WrongValuesShownGood.Should().Be(0);
    }

    [Fact]
    public void Judge_InputChangeOtherThanTheFieldsLatestSetting_IsAChangeNothingExplains()
    {
        var settings = new[] { Change(5, ProtocolArea.I, 12, [0, 0, 0, 0], [1, 2, 3, 4]), Change(8, ProtocolArea.I, 12, [1, 2, 3, 4], [5, 6, 7, 8]) };

        var result = Judge([], [], [Change(10, ProtocolArea.I, 12, [0, 0, 0, 0], [1, 2, 3, 4])], settings);

        result.FieldChanges.Should().Be(0);
        result.ExecutedNeverSent.Should().Be(1);
        result.Findings.Should().Equal("I bytes 12-15 changed 00000000 -> 01020304: not what the field set");
    }

    [Fact]
    public void Judge_LastSmWordShownWithBytesItNeverHeldTogether_IsAWrongValueShownGood()
    {
        var settings = new[] { Change(5, ProtocolArea.SM, 546, [0, 0, 0, 0], [1, 2, 3, 4]), Change(15, ProtocolArea.SM, 546, [1, 2, 3, 4], [5, 6, 7, 8]) };
        var changes = new[] { Change(6, ProtocolArea.SM, 546, [0, 0, 0, 0], [1, 2, 3, 4]), Change(16, ProtocolArea.SM, 546, [1, 2, 3, 4], [5, 6, 7, 8]) };

        var result = Judge([], [Shown("SMW548", [0x03, 0x08], 1, 20), Shown("SMW548", [0x07, 0x08], 1, 20)], changes, settings);

        result.WrongValuesShownGood.Should().Be(1);
        result.FieldChanges.Should().Be(2);
    }

    [Fact]
    public void Judge_ChangeOutsideTheRegion_IsAChangeNothingExplains()
    {
        var result = Judge([], [], [new MemoryChange(5, ProtocolArea.M, 3, [0], [8])]);

        result.ExecutedNeverSent.Should().Be(1);
    }

    private static SoakJudgement Judge(
        IReadOnlyList<SoakWrite> writes, IReadOnlyList<ShownValue> shown, IReadOnlyList<MemoryChange> changes, IReadOnlyList<MemoryChange>? settings = null) =>
        new SoakJudge(Region, Image()).Judge(writes, shown, changes, settings ?? []);

    /// <summary>All zeros: V 1000-1007, all of Q, M and I, the last SM window of a CPU 226.</summary>
    private static MemoryImage Image() => new(
    [
        (new WatchedBytes(ProtocolArea.V, 1000, 8), new byte[8]),
        (new WatchedBytes(ProtocolArea.Q, 0, 16), new byte[16]),
        (new WatchedBytes(ProtocolArea.M, 0, 32), new byte[32]),
        (new WatchedBytes(ProtocolArea.I, 0, 16), new byte[16]),
        (new WatchedBytes(ProtocolArea.SM, 546, 4), new byte[4]),
    ]);

    private static SoakWrite Write(int number, string address, byte[] value, WriteOutcome outcome, long sent = 0) =>
        new(number, PlcAddress.Parse(address), [.. value], sent, sent + 5, outcome);

    private static ShownValue Shown(string address, byte[] value, long from, long until) => new(PlcAddress.Parse(address), [.. value], from, until);

    private static MemoryChange Change(long at, ProtocolArea area, int first, byte[] before, byte[] after) =>
        new(at, area, first, [.. before], ImmutableArray.Create(after));
}

using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Polling;
using OperatorPanel.Core.Projects;
using OperatorPanel.Historian.Recording;

namespace OperatorPanel.Historian.Tests.Recording;

/// <summary>Which steps of a value pass the deadband.</summary>
public sealed class DeadbandTests
{
    private static readonly RecordedTag Word = new(new Station(2), PlcAddress.Parse("VW150"), "Level", DisplayFormat.Signed, null);

    [Theory]
    [InlineData(1000, 1005, 0.5, false)] // exactly the band: not more than it
    [InlineData(1000, 1006, 0.5, true)]
    [InlineData(1000, 994, 0.5, true)]
    [InlineData(0, 1, 0.5, true)] // the band of 0 is 0: any step away from zero
    [InlineData(1000, 1001, 0, true)]
    [InlineData(-1000, -1004, 0.5, false)] // the band is of the magnitude
    public void Passes_ProjectPercentage_JudgesTheStep(int from, int to, double percent, bool expected)
    {
        Deadband.Passes(Word, HistorySettings.Default with { DeadbandPercent = percent }, Good(from), Good(to)).Should().Be(expected);
    }

    [Fact]
    public void Passes_QualityChangeWithTheSameValue_Passes()
    {
        var stale = Good(1000) with { Quality = ValueQuality.Stale };

        Deadband.Passes(Word, HistorySettings.Default, Good(1000), stale).Should().BeTrue();
    }

    [Fact]
    public void Passes_NothingRecordedYet_Passes()
    {
        Deadband.Passes(Word, HistorySettings.Default, null, Good(1)).Should().BeTrue();
    }

    [Fact]
    public void Passes_TagDeadband_OverridesThePercentage()
    {
        var tag = Word with { Deadband = 10 };

        Deadband.Passes(tag, HistorySettings.Default, Good(1000), Good(1010)).Should().BeFalse();
        Deadband.Passes(tag, HistorySettings.Default, Good(1000), Good(1011)).Should().BeTrue();
    }

    private static PolledValue Good(int value) =>
        PolledValue.Good(ImmutableArray.Create((byte)((ushort)value >> 8), (byte)value), DateTimeOffset.UnixEpoch);
}

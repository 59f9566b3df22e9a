using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Operations;
using OperatorPanel.Stl.Instructions;
using static OperatorPanel.Simulator.Tests.Stl.StlTestPrograms;

namespace OperatorPanel.Simulator.Tests.Stl.Operations;

/// <summary>
/// The simulator's instruction table against the manual's (the Stl project's StlInstructionTable, docs/stl-instructions.md):
/// every instruction either runs with a time and a handler or is refused with a reason, and the times are the
/// published ones where there are any.
/// </summary>
public sealed class StlOperationsTests
{
    [Fact]
    public void EveryInstructionOfTheManual_RunsOrIsRefusedWithAReason()
    {
        var unaccounted = StlInstructionTable.All.Select(s => s.Mnemonic)
            .Where(m => StlOperations.TryGet(m, out _) == StlOperations.NotExecuted.ContainsKey(m));

        unaccounted.Should().BeEmpty("each mnemonic is in exactly one of the two lists");
        StlOperations.NotExecuted.Values.Should().AllSatisfy(reason => reason.Should().NotBeNullOrWhiteSpace());
    }

    [Fact]
    public void EveryRow_IsAnInstructionOfTheManual()
    {
        StlOperations.All.Select(o => o.Mnemonic).Concat(StlOperations.NotExecuted.Keys)
            .Where(m => !StlInstructionTable.TryGet(m, out _)).Should().BeEmpty();
        StlOperations.All.Select(o => o.Mnemonic).Should().OnlyHaveUniqueItems();
    }

    [Fact]
    public void EveryOpCode_HasARow()
    {
        Enum.GetValues<StlOpCode>().Except(StlOperations.All.Select(o => o.Code)).Should().BeEmpty();
    }

    [Fact]
    public void EveryRow_HasAHandlerAndATimeWithItsSource()
    {
        StlOperations.All.Should().AllSatisfy(o =>
        {
            o.Execute.Should().NotBeNull(o.Mnemonic);
            o.Time.Source.Should().NotBeNullOrWhiteSpace(o.Mnemonic);
        });
        StlOperations.All.Where(o => o.Time.Nanoseconds <= 0).Select(o => o.Mnemonic).Should().Equal(["LBL"], "every instruction takes time but a jump target");
    }

    [Theory]
    [InlineData("TON")]
    [InlineData("TONR")]
    [InlineData("TOF")]
    [InlineData("CTU")]
    [InlineData("CTD")]
    [InlineData("CTUD")]
    public void TimersAndCounters_TakeThePublishedHighEnd64Us(string mnemonic)
    {
        StlOperations.TryGet(mnemonic, out var operation).Should().BeTrue();

        // C79000-G7076-C233-01 Tables A-2 to A-4: "Timer/Counter execution speed 50 us to 64 us per instruction".
        operation!.Time.Nanoseconds.Should().Be(64_000);
    }

    [Theory]
    [InlineData("LD", 370)] //       [A2] Boolean 0.37 us
    [InlineData("MOVW", 34_000)] //  [A2] Move Word 34 us
    [InlineData("+I", 46_000)] //    [A2] single precision math 46 us
    [InlineData("+R", 400_000)] //   [A2] real math 100-400 us, the high end
    [InlineData("RCV", 80_000)] //   [F3] p. 458
    [InlineData("RET", 13_000)] //   [F3] p. 458
    [InlineData("RETI", 23_000)] //  [F3] p. 458
    public void PublishedFigures_AreTheManuals(string mnemonic, long nanoseconds)
    {
        StlOperations.TryGet(mnemonic, out var operation).Should().BeTrue();

        operation!.Time.Nanoseconds.Should().Be(nanoseconds);
    }

    [Fact]
    public void TwentyTimers_ScanTakesTheirPublishedTimePlusHousekeeping()
    {
        var body = string.Join("\nNetwork 2\n", Enumerable.Range(37, 20).Select(t => $"LD     I0.0\nTON    T{t}, +10"));
        var plc = Plc(body);
        var scans = new List<StlScan>();
        plc.ScanCompleted += (_, scan) => scans.Add(scan);
        plc.RunUntil(TimeSpan.FromMilliseconds(10));

        // 20 x (LD 0.37 us + TON 64 us) + 250 us housekeeping; before this table a TON took the 400 us fallback (8.25 ms).
        scans.Should().NotBeEmpty();
        scans[0].Busy.Should().Be(TimeSpan.FromTicks(((20 * (370 + 64_000)) + 250_000) / 100));
    }
}

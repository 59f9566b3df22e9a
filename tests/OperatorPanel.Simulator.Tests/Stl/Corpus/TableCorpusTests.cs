namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>Tables.awl: the LIFO example of C79000-G7076-C233-01 p. 9-109 (Figure 9-36), FIFO, ATT, FND and FILL.</summary>
public sealed class TableCorpusTests
{
    [Fact]
    public void Att_FirstScan_BuildsTheManualsTable()
    {
        var run = CorpusProgram.Run("Tables.awl", 0.05);

        new[] { run.Value("VW200"), run.Value("VW202"), run.Value("VW204"), run.Value("VW206"), run.Value("VW208") }
            .Should().Equal(6, 3, 5431, 8942, 1234);
    }

    [Fact]
    public void Lifo_TheManualsExample_TakesTheNewestEntry()
    {
        var run = CorpusProgram.Run("Tables.awl", 0.2, "I4.0=1@0.1s");

        run.Value("VW300").Should().Be(1234);
        run.Value("VW202").Should().Be(2);
        run.Value("VW204").Should().Be(5431);
        run.Value("VW206").Should().Be(8942);
    }

    [Fact]
    public void Fifo_TakesTheOldestAndMovesTheRestUp()
    {
        var run = CorpusProgram.Run("Tables.awl", 0.2, "I4.1=1@0.1s");

        run.Value("VW400").Should().Be(5431);
        run.Value("VW202").Should().Be(2);
        run.Value("VW204").Should().Be(8942);
        run.Value("VW206").Should().Be(1234);
    }

    [Fact]
    public void Fifo_EmptyTable_SetsSm15AndLeavesData()
    {
        var run = CorpusProgram.Run("Tables.awl", 1, CorpusProgram.Pulses("I4.1", 0.1, 0.2, 0.3, 0.4));

        run.Value("VW400").Should().Be(1234, "the third FIFO took the last entry; the fourth found none");
        run.Value("VW202").Should().Be(0);
        ((int)run.Value("VB20") & 0x20).Should().Be(0x20, "SM1.5: empty table");
    }

    [Fact]
    public void Att_FullTable_SetsSm14AndAddsNothing()
    {
        var run = CorpusProgram.Run("Tables.awl", 1, ["VW10=77", .. CorpusProgram.Pulses("I4.2", 0.1, 0.2, 0.3, 0.4)]);

        run.Value("VW202").Should().Be(6, "TL 6");
        run.Value("VW214").Should().Be(77);
        ((int)run.Value("VB20") & 0x10).Should().Be(0x10, "SM1.4: the fourth ATT found the table full");
    }

    [Theory]
    [InlineData("VW520", 1)]
    [InlineData("VW522", 1)]
    [InlineData("VW524", 3)]
    [InlineData("VW526", 2)]
    public void Fnd_SearchesFromIndex_LeavesFirstMatchOrEntryCount(string index, int expected) =>
        CorpusProgram.Run("Tables.awl", 0.05).Value(index).Should().Be(expected);

    [Fact]
    public void Fill_WritesTheValueIntoNWords()
    {
        var run = CorpusProgram.Run("Tables.awl", 0.05);

        new[] { run.Value("VW600"), run.Value("VW602"), run.Value("VW604"), run.Value("VW606") }
            .Should().Equal(unchecked((short)0xAA55), unchecked((short)0xAA55), unchecked((short)0xAA55), 0);
    }
}

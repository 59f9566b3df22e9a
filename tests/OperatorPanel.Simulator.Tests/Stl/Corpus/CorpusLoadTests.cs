using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Operations;
using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>The corpus as a whole: Micro/WIN's export form, every implemented instruction used, the unimplemented ones refused.</summary>
public sealed class CorpusLoadTests
{
    /// <summary>Instructions the corpus leaves out, with the reason: the handler owns the port, and Micro/WIN adds the returns.</summary>
    private static readonly string[] NotInCorpus = ["RCV", "XMT", "RET", "RETI", "CRETI", "MEND", "END", "NOP"];

    public static TheoryData<string> Runnable =>
        [.. Directory.GetFiles(CorpusProgram.Folder(), "*.awl").Select(f => Path.GetFileName(f)).Where(n => n != "Refused.awl")];

    [Theory]
    [MemberData(nameof(Runnable))]
    public void CorpusProgram_IsAMicroWinExport_AndLoads(string name)
    {
        var text = CorpusProgram.Text(name);

        text.Should().StartWith("ORGANIZATION_BLOCK MAIN:OB1\r\nTITLE=");
        text.Replace("\r\n", string.Empty, StringComparison.Ordinal).Should().NotContain("\n", "Micro/WIN writes CRLF");
        text.Should().Contain("END_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK ").And.Contain(":SBR0\r\n").And.EndWith("END_INTERRUPT_BLOCK\r\n");
        CorpusProgram.Load(name).InstructionCount.Should().BePositive();
    }

    [Fact]
    public void Corpus_UsesEveryImplementedInstruction()
    {
        var used = Directory.GetFiles(CorpusProgram.Folder(), "*.awl")
            .SelectMany(f => AwlParser.Parse(File.ReadAllText(f)).Program.Blocks)
            .SelectMany(b => b.Instructions)
            .Select(i => i.Mnemonic)
            .ToHashSet(StringComparer.Ordinal);

        // Compares and FND count once per op code (LD/A/O of B/W/D, of R): the corpus need not spell every relation.
        var missing = StlOperations.All.Where(o => !NotInCorpus.Contains(o.Mnemonic)).GroupBy(o => o.Code)
            .Where(g => !g.Any(o => used.Contains(o.Mnemonic))).Select(g => g.First().Mnemonic);

        missing.Should().BeEmpty();
    }

    [Fact]
    public void Refused_UnimplementedInstructions_NamedWithTheirLinesBeforeRunning()
    {
        var load = StlProgramLoader.Load(CorpusProgram.Text("Refused.awl"), CorpusProgram.Cpu224);

        load.Program.Should().BeNull();
        load.Diagnostics.Select(d => (d.Line, d.Message.Split(' ')[0])).Should().Equal((10, "PID"), (11, "NETR"), (12, "NETW"));
        load.Warnings.Select(d => (d.Line, d.Message.Split(':')[0])).Should().Equal((7, "HDEF"), (8, "HSC"), (9, "PLS"));
    }

    [Fact]
    public void Refused_Strict_AlsoRefusesWhatDoesNothing()
    {
        var load = StlProgramLoader.Load(CorpusProgram.Text("Refused.awl"), CorpusProgram.Cpu224, new StlLoadOptions { Strict = true });

        load.Diagnostics.Select(d => (d.Line, d.Message.Split(' ')[0])).Should().Equal(
            (7, "HDEF"), (8, "HSC"), (9, "PLS"), (10, "PID"), (11, "NETR"), (12, "NETW"));
    }
}

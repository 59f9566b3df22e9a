using OperatorPanel.Simulator.Stl;
using OperatorPanel.Stl;
using OperatorPanel.StlGen.Diagnostics;
using OperatorPanel.StlGen.Merge;
using OperatorPanel.StlGen.Tests.Golden;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Merge;

public sealed class HandlerMergerTests
{
    private static readonly string Filler = UserProgram.Read("Filler.awl");

    [Fact]
    public void Merge_ExportedFillerProgram_MatchesGoldenFile()
    {
        var result = HandlerMerger.Merge(Filler, UserProgram.Cpu224);

        result.Diagnostics.Should().BeEmpty();
        GoldenFile.Match("Filler-merged.awl", result.MergedText);
    }

    [Fact]
    public void Merge_ExportedFillerProgram_ParsesAndLoadsForTheCpu()
    {
        var result = HandlerMerger.Merge(Filler, UserProgram.Cpu224);

        AwlParser.Parse(result.MergedText).Diagnostics.Should().BeEmpty();
        var loaded = StlProgramLoader.Load(result.MergedText, UserProgram.Cpu224.Cpu);
        loaded.Diagnostics.Should().BeEmpty();
        loaded.Succeeded.Should().BeTrue();
    }

    [Fact]
    public void Merge_ExportedFillerProgram_KeepsEveryUserLineInOrderButTheNetworkNumbers()
    {
        var merged = HandlerMerger.Merge(Filler, UserProgram.Cpu224).MergedText.Split("\r\n").Select(WithoutNetworkNumber).ToArray();
        var user = Filler.Split("\r\n").Select(WithoutNetworkNumber);

        var position = 0;
        foreach (var line in user.Where(l => l.Length > 0))
        {
            position = Array.IndexOf(merged, line, position);
            position.Should().BeGreaterThanOrEqualTo(0, $"user line '{line}' must be in the merged file, in order");
            position++;
        }
    }

    [Fact]
    public void Merge_ExportedFillerProgram_KeepsTheUserNetworksUnchanged()
    {
        var user = AwlParser.Parse(Filler).Program;
        var merged = AwlParser.Parse(HandlerMerger.Merge(Filler, UserProgram.Cpu224).MergedText).Program;

        foreach (var block in user.Blocks)
        {
            var same = merged.Find(block.Name)!;
            var userNetworks = block.Networks.Select(n => (n.Title, Code: n.Instructions.Select(i => (i.Mnemonic, string.Join(",", i.Operands)))));
            var mergedNetworks = same.Networks.Skip(block.Kind == AwlBlockKind.OrganizationBlock ? 1 : 0)
                .Select(n => (n.Title, Code: n.Instructions.Select(i => (i.Mnemonic, string.Join(",", i.Operands)))));
            mergedNetworks.Select(n => (n.Title, string.Join(";", n.Code))).Should().Equal(userNetworks.Select(n => (n.Title, string.Join(";", n.Code))));
        }
    }

    [Fact]
    public void Merge_ExportedFillerProgram_CallsTheHandlerInTheFirstNetworkAndOrdersBlocksByNumber()
    {
        var merged = AwlParser.Parse(HandlerMerger.Merge(Filler, UserProgram.Cpu224).MergedText).Program;

        var first = merged.MainBlock!.Networks[0];
        first.Title.Should().Be("Operator panel: call the port handler every scan");
        first.Comments.Should().NotBeEmpty();
        first.Instructions.Select(i => $"{i.Mnemonic} {string.Join(", ", i.Operands)}").Should().Equal("LD SM0.0", "CALL OP_PANEL");
        merged.Blocks.Select(b => $"{b.Name}:{b.DefaultName}").Should().Equal(
            "MAIN:OB1", "SCALE:SBR_0", "COUNT_BOTTLES:SBR_1", "OP_PANEL:SBR_63", "TICK:INT_0", "OP_RX:INT_125", "OP_DELAY:INT_126", "OP_TX:INT_127");
    }

    [Fact]
    public void Merge_HandlerNumbersBetweenUserBlocks_InsertsInNumberOrder()
    {
        var result = HandlerMerger.Merge(Filler, UserProgram.Cpu224 with { FirstSubroutine = 1, FirstInterrupt = 0 });

        result.Errors.Select(d => d.Id).Should().Equal(StlDiagnostics.SubroutineNumberInUse, StlDiagnostics.InterruptNumberInUse);
        var moved = HandlerMerger.Merge(Filler, UserProgram.Cpu224 with { FirstSubroutine = 5, FirstInterrupt = 1, BufferStart = 1000 });
        AwlParser.Parse(moved.MergedText).Program.Blocks.Select(b => b.DefaultName).Should().Equal(
            "OB1", "SBR_0", "SBR_1", "SBR_5", "INT_0", "INT_1", "INT_2", "INT_3");
    }

    [Fact]
    public void Merge_AnyInput_WritesAsciiWithCrlfAfterEveryLine()
    {
        var lfOnly = Filler.Replace("\r\n", "\n", StringComparison.Ordinal);

        var text = HandlerMerger.Merge(lfOnly, UserProgram.Cpu224).MergedText;

        text.Should().EndWith("END_INTERRUPT_BLOCK\r\n");
        text.Replace("\r\n", string.Empty, StringComparison.Ordinal).Should().NotContain("\n").And.NotContain("\r");
        text.Should().Be(HandlerMerger.Merge(Filler, UserProgram.Cpu224).MergedText);
        text.All(c => c is '\r' or '\n' or '\t' or (>= ' ' and <= '~')).Should().BeTrue();
    }

    [Fact]
    public void Merge_UserLineWithALoneCarriageReturn_IsRefusedNamingTheLineNotThrown()
    {
        var user = Filler.Replace("Micro/WIN 4.0 SP9\r\n", "Micro/WIN 4.0 SP9\r999\r\n", StringComparison.Ordinal);

        var result = HandlerMerger.Merge(user, UserProgram.Cpu224);

        result.MergedText.Should().BeEmpty();
        result.Diagnostics.Should().ContainSingle().Which.Message.Should().Contain("a carriage return (16#0D) inside the line");
    }

    [Fact]
    public void Merge_EveryBlock_CountsItsNetworksFromOne()
    {
        var user = UserProgram.WithBlocks(
            ["LD     SM0.0", "=      Q0.0", "Network 7 // second", "LD     SM0.1", "=      Q0.1", "Network 7 // third, numbered twice by hand", "LD     I0.0", "=      Q0.2"],
            ["SUBROUTINE_BLOCK SBR_0:SBR0", "BEGIN", "Network 4 // first of SBR_0", "Network 9 //   second of SBR_0, its comment kept", "END_SUBROUTINE_BLOCK"]);

        var merged = HandlerMerger.Merge(user, UserProgram.Cpu224).MergedText;

        var program = AwlParser.Parse(merged).Program;
        program.Blocks.Should().AllSatisfy(b => b.Networks.Select(n => n.Number).Should().Equal(Enumerable.Range(1, b.Networks.Length), b.Name));
        merged.Should().Contain("\r\nNetwork 2 // test\r\n").And.Contain("\r\nNetwork 3 // second\r\n")
            .And.Contain("\r\nNetwork 4 // third, numbered twice by hand\r\n").And.Contain("\r\nNetwork 2 //   second of SBR_0, its comment kept\r\n");
    }

    /// <summary>"Network 7 // title" as "Network # // title": the merge renumbers networks and keeps the rest of the line.</summary>
    private static string WithoutNetworkNumber(string line) =>
        System.Text.RegularExpressions.Regex.Replace(line, "^(Network )\\d+", "$1#");
}

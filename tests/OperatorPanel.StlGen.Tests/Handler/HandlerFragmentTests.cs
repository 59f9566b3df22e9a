using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Model;
using OperatorPanel.StlGen.Options;
using OperatorPanel.StlGen.Tests.Golden;

namespace OperatorPanel.StlGen.Tests.Handler;

public sealed class HandlerFragmentTests
{
    [Theory]
    [InlineData(9600, Parity.None, 8, "16#09")]
    [InlineData(19200, Parity.Even, 8, "16#45")]
    [InlineData(38400, Parity.Odd, 7, "16#E1")]
    [InlineData(115200, Parity.None, 8, "16#19")]
    public void Subroutine_FreeportNetwork_SetsSmb30FromTheLineSettings(int baud, Parity parity, int dataBits, string smb30)
    {
        var program = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), BaudRate = baud, Parity = parity, DataBits = dataBits }).Program!;

        Instructions(program, StlBlockKind.Subroutine, 0).Should().Contain($"MOVB {smb30}, SMB30");
    }

    [Fact]
    public void Subroutine_Port1_UsesSmb130AndEvents24And26()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu226Port1Station17).Program!;
        var freeport = Instructions(program, StlBlockKind.Subroutine, 0);

        freeport.Should().Contain("MOVB 16#E4, SMB187").And.Contain("MOVW 100, SMW192")
            .And.Contain("ATCH OP_RX, 24").And.Contain("ATCH OP_TX, 26")
            .And.Contain("RCV VB1000, 1");
        Instructions(program, StlBlockKind.Subroutine, 1).Should().Contain("MOVB 0, SMB130");
    }

    [Fact]
    public void Subroutine_TermNetwork_FollowsTheFallingEdgeOfSm07()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2).Program!;

        Instructions(program, StlBlockKind.Subroutine, 1).Take(5).Should().Equal("LDN SM0.7", "A V8059.7", "LD SM0.1", "AN SM0.7", "OLD");
        Instructions(program, StlBlockKind.Subroutine, 2).Should().Equal("LD SM0.7", "= V8059.7");
    }

    [Fact]
    public void Receive_StationCheck_ComparesWithTheConfiguredStation()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu226Port1Station17).Program!;

        program.Blocks[1].Networks.SelectMany(n => n.Instructions).Select(AwlText).Should().Contain("LDB<> VB1256, 17");
    }

    [Fact]
    public void Delay_Interrupt_DetachesEvent10ThenTransmitsTheCoveredCharactersFromSent()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2).Program!;

        // COVERED = VD8040, SENT = VD8044 (SAVE's AC0 and AC1 double words); SENT is buffer byte 0 for the first chunk.
        program.Blocks[3].Networks.Single().Instructions.Select(AwlText).Should().Equal(
            "LD SM0.0", "DTCH 10", "MOVD VD8040, AC0", "-D VD8044, AC0", "MOVB AC0, *VD8044", "XMT *VD8044, 0", "MOVD VD8040, VD8044");
    }

    [Fact]
    public void Transmit_Interrupt_SendsWhatIsCoveredElseWaitsElseReceivesAfterTheGreaterThan()
    {
        var program = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2).Program!;

        program.Blocks[4].Networks.Select(n => n.Instructions.Select(AwlText)).Should().SatisfyRespectively(
            more => more.Should().Equal(
                "LDD<> VD8040, VD8044", "MOVD VD8040, AC0", "-D VD8044, AC0", "MOVB AC0, *VD8044", "XMT *VD8044, 0", "MOVD VD8040, VD8044", "CRETI"),
            wait => wait.Should().Equal("LDB<> *VD8044, 16#3E", "R V8059.2, 1", "CRETI"),
            done => done.Should().Equal("LD SM0.0", "RCV VB7764, 0"));
    }

    [Fact]
    public void Writable_MaskWithoutSm_RefusesSmAndSkipsTheSmByteChecks()
    {
        var program = HandlerGenerator.Generate(new HandlerOptions { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), WriteMask = 0x1C }).Program!;
        var all = program.Blocks[1].Networks.SelectMany(n => n.Instructions).Select(AwlText).ToList();

        all.Should().Contain("LDB= VB7772, 5").And.NotContain(i => i.StartsWith("AW< ", StringComparison.Ordinal));
    }

    [Fact]
    public void Generate_Cpu224_CountsEveryInstruction()
    {
        var result = HandlerGenerator.Generate(HandlerGoldenTests.Cpu224Port0Station2);
        var lines = result.AwlText.Split("\r\n");

        result.Stats!.Instructions.Should().Be(lines.Count(l => l.Length > 0 && !l.StartsWith("//", StringComparison.Ordinal) && !IsStructure(l)));
    }

    private static bool IsStructure(string line) =>
        line.StartsWith("Network ", StringComparison.Ordinal) || line.StartsWith("TITLE=", StringComparison.Ordinal) || line == "BEGIN"
        || line.Contains("_BLOCK", StringComparison.Ordinal);

    private static string AwlText(StlInstruction i) => (i.Mnemonic + " " + string.Join(", ", i.Operands)).Trim();

    private static List<string> Instructions(StlProgram program, StlBlockKind kind, int network) =>
        [.. program.Blocks.First(b => b.Kind == kind).Networks[network].Instructions.Select(AwlText)];
}

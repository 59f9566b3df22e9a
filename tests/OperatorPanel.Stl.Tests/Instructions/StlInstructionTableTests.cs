using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Stl.Tests.Instructions;

public sealed class StlInstructionTableTests
{
    [Fact]
    public void All_ListsEveryMnemonicOnce()
    {
        StlInstructionTable.All.Select(s => s.Mnemonic).Should().OnlyHaveUniqueItems();
        StlInstructionTable.All.Should().HaveCountGreaterThan(230);
    }

    [Theory]
    [InlineData("MOVW", "IN", "IW, QW, VW, MW, SMW, SW, LW, T, C, AIW, AC, *VD, *LD, *AC, constant")]
    [InlineData("MOVW", "OUT", "IW, QW, VW, MW, SMW, SW, LW, T, C, AQW, AC, *VD, *LD, *AC")]
    [InlineData("LD", "bit", "I, Q, V, M, SM, S, L, T, C")]
    [InlineData("MOVD", "IN", "ID, QD, VD, MD, SMD, SD, LD, HC, AC, *VD, *LD, *AC, &VB, constant")]
    [InlineData("XMT", "TBL", "IB, QB, VB, MB, SMB, SB, *VD, *LD, *AC")]
    [InlineData("TON", "Txxx", "T")]
    public void Operand_KindsAreTheManuals(string mnemonic, string operand, string kinds)
    {
        StlInstructionTable.TryGet(mnemonic, out var spec).Should().BeTrue();

        StlOperandKindsText.Describe(spec!.Operands.Single(o => o.Name == operand)).Should().Be(kinds);
    }

    [Theory]
    [InlineData("SLW")]
    [InlineData("SRB")]
    [InlineData("RLD")]
    [InlineData("SHRB")]
    [InlineData("LDW>=")]
    [InlineData("LDS")]
    [InlineData("AENO")]
    [InlineData("=I")]
    [InlineData("FND<>")]
    [InlineData("LDS<>")]
    public void TryGet_RealMnemonic_IsFound(string mnemonic) =>
        StlInstructionTable.TryGet(mnemonic, out _).Should().BeTrue();

    [Theory]
    [InlineData("SHLW")]
    [InlineData("SHRW")]
    [InlineData("SHLB")]
    [InlineData("LDW==")]
    [InlineData("LDS<")]
    [InlineData("MOVX")]
    public void TryGet_MnemonicTheS7200DoesNotHave_IsNotFound(string mnemonic) =>
        StlInstructionTable.TryGet(mnemonic, out _).Should().BeFalse();

    [Fact]
    public void ImplicitBlockEnds_AreWrittenNowhere()
    {
        var implicitEnds = StlInstructionTable.All.Where(s => s.Placement == StlPlacement.None).Select(s => s.Mnemonic);

        implicitEnds.Should().BeEquivalentTo("MEND", "RET", "RETI");
    }

    [Fact]
    public void ArithmeticAndConversion_SetTheManualsStatusBits()
    {
        Bits("/I").Should().Be(StlStatusBits.Zero | StlStatusBits.Overflow | StlStatusBits.Negative | StlStatusBits.DivideByZero);
        Bits("ATT").Should().Be(StlStatusBits.TableFull);
        Bits("FIFO").Should().Be(StlStatusBits.TableEmpty);
        Bits("BCDI").Should().Be(StlStatusBits.BcdError);
        Bits("ATH").Should().Be(StlStatusBits.AsciiError);
        Bits("MOVB").Should().Be(StlStatusBits.None);
    }

    [Fact]
    public void CountedOperands_WidenByTheCount()
    {
        StlInstructionTable.TryGet("BMW", out var bmw).Should().BeTrue();
        StlInstructionTable.TryGet("SHRB", out var shrb).Should().BeTrue();

        (bmw!.CountIndex, bmw.Operands[0].Extent, bmw.Operands[1].Extent).Should().Be((2, StlExtent.Count, StlExtent.Count));
        (shrb!.CountIndex, shrb.Operands[1].Extent, shrb.Operands[1].IsWritten).Should().Be((2, StlExtent.AbsoluteCount, true));
    }

    private static StlStatusBits Bits(string mnemonic) =>
        StlInstructionTable.TryGet(mnemonic, out var spec) ? spec.StatusBits : throw new InvalidOperationException(mnemonic);
}

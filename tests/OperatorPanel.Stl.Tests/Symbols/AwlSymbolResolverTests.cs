using OperatorPanel.Stl.Symbols;

namespace OperatorPanel.Stl.Tests.Symbols;

public sealed class AwlSymbolResolverTests
{
    private static readonly AwlSymbolTable Table = AwlSymbolTable.Parse("Always_On\tSM0.0\r\nCount\tVW10\r\nLamp\tQ0.0\r\n");

    [Fact]
    public void Resolve_SymbolicOperands_BecomeTheirAddressesOnTheSameLines()
    {
        var program = AwlParser.Parse("ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nLD     Always_On\r\nINCW   Count\r\nLDW>=  Count, +3\r\n=      Lamp\r\nCALL   FILL_SUB, Count\r\nEND_ORGANIZATION_BLOCK\r\n").Program;

        var (resolved, unknown) = AwlSymbolResolver.Resolve(program, Table);

        unknown.Should().BeEmpty();
        resolved.MainBlock!.Instructions.Select(i => (i.Line, string.Join(",", i.Operands))).Should().Equal(
            (4, "SM0.0"), (5, "VW10"), (6, "VW10,+3"), (7, "Q0.0"), (8, "FILL_SUB,VW10"));
    }

    [Fact]
    public void Resolve_SymbolNotInTheTable_NamedWithItsLine()
    {
        var program = AwlParser.Parse("ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nLD     Start_PB\r\n=      Lamp\r\nEND_ORGANIZATION_BLOCK\r\n").Program;

        var (_, unknown) = AwlSymbolResolver.Resolve(program, Table);

        unknown.Select(d => d.ToString()).Should().Equal("line 4: LD: symbol 'Start_PB' is not in the symbol table");
    }
}

using OperatorPanel.Stl.Symbols;

namespace OperatorPanel.Stl.Tests.Symbols;

public sealed class AwlSymbolTableTests
{
    [Fact]
    public void Parse_MicroWinExportWithIconColumnsAndHeader_EveryAddressKind()
    {
        var table = AwlSymbolTable.Parse(
            "\t\tSymbol\tAddress\tComment\r\n\t\tStart_PB\tI0.0\tStart\r\n\t\tSetpoint\tVW100\t\r\n\t\tCycle_Timer\tT37\tcycle\r\n\t\tPort_Ctrl\tSMB30\t\r\n");

        table.Rejected.Should().BeEmpty();
        table.Count.Should().Be(4);
        table.TryGetAddress("Setpoint", out var setpoint).Should().BeTrue();
        setpoint.Should().Be("VW100");
        table.TryGetAddress("cycle_timer", out var timer).Should().BeTrue("no source says Micro/WIN tells case apart in symbols");
        timer.Should().Be("T37");
        table.TryGetAddress("Port_Ctrl", out var port).Should().BeTrue();
        port.Should().Be("SMB30");
    }

    [Fact]
    public void Parse_LinesWithoutAddressOrSymbol_RejectedWithTheirNumbers()
    {
        var table = AwlSymbolTable.Parse("Symbol\tAddress\r\nA\tVW0\r\nnot a symbol line\r\n\tVW2\tcomment\r\nA\tVW4\r\n");

        table.Rejected.Select(r => r.Line).Should().Equal(3, 4, 5);
        table.Rejected[2].Message.Should().Contain("A is given twice");
    }
}

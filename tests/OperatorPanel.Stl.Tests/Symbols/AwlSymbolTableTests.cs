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

    [Fact]
    public void Parse_SemicolonCsvFromASpreadsheet_ReadLikeTheTabText()
    {
        // As Sebaasu/xk335b-scada keeps its S7-200 table: Symbol;Address;Comment, CRLF, a comment with a comma.
        var table = AwlSymbolTable.Parse("Symbol;Address;Comment\r\nSens_Origen;I0.0;Sensor (homing, servo)\r\nSetpoint;VW100;\r\n\"Cycle;Timer\";T37;quoted\r\n");

        table.Rejected.Should().BeEmpty();
        table.Count.Should().Be(3);
        table.TryGetAddress("Sens_Origen", out var sensor).Should().BeTrue();
        sensor.Should().Be("I0.0");
        table.TryGetAddress("Cycle;Timer", out var timer).Should().BeTrue("a quoted cell keeps its semicolon");
        timer.Should().Be("T37");
    }

    [Fact]
    public void Parse_CommaCsv_CommentSplitByACommaStillGivesTheSymbol()
    {
        var table = AwlSymbolTable.Parse("Symbol,Address,Comment\nStart_PB,I0.0,green, on the door\nLevel,VW10,\n");

        table.Rejected.Should().BeEmpty();
        table.TryGetAddress("Start_PB", out var start).Should().BeTrue();
        start.Should().Be("I0.0");
        table.TryGetAddress("Level", out var level).Should().BeTrue();
        level.Should().Be("VW10");
    }

    [Fact]
    public void Parse_TabText_SemicolonsInACommentStayInTheComment()
    {
        var table = AwlSymbolTable.Parse("Motor_On\tQ0.0\tstarts; stops at TERM\n");

        table.Rejected.Should().BeEmpty();
        table.TryGetAddress("Motor_On", out var motor).Should().BeTrue();
        motor.Should().Be("Q0.0");
    }
}

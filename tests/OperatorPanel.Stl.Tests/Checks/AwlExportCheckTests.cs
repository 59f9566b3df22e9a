using OperatorPanel.Stl.Checks;

namespace OperatorPanel.Stl.Tests.Checks;

public sealed class AwlExportCheckTests
{
    private const string Empty = "BEGIN\r\nNetwork 1 // Network Title\r\n";

    private static AwlExportFindings Check(string text) => AwlExportCheck.Check(AwlParser.Parse(text).Program);

    [Fact]
    public void Check_Ob1HeaderWithoutName_RefusedAtItsLine()
    {
        var found = Check($"ORGANIZATION_BLOCK OB1\r\n{Empty}END_ORGANIZATION_BLOCK\r\n");

        found.Refusals.Select(r => r.ToString()).Should().Equal(
            "line 1: AWL012 the header of OB1 has no name: Micro/WIN imports ORGANIZATION_BLOCK NAME:OB1 (as it exports, e.g. ORGANIZATION_BLOCK MAIN:OB1)");
    }

    [Theory]
    [InlineData("CALL   VALVES", "CALL VALVES: the file has no subroutine of that name")]
    [InlineData("ATCH   ON_EDGE, 0", "ATCH ON_EDGE: the file has no interrupt routine of that name")]
    [InlineData("CALL   SBR_1", "CALL SBR_1: the file has no subroutine")]
    public void Check_CallOrAttachToAbsentBlock_RefusedAtItsLine(string instruction, string reason)
    {
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.1\r\n{instruction}\r\nEND_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK SBR_0:SBR0\r\n{Empty}END_SUBROUTINE_BLOCK\r\n");

        found.Refusals.Should().ContainSingle().Which.ToString().Should().StartWith($"line 5: AWL013 {reason}");
    }

    [Theory]
    [InlineData("CALL   SBR_0")]
    [InlineData("CALL   SBR0")]
    [InlineData("CALL   VALVES")]
    public void Check_CallByNameDefaultNameOrNumber_Accepted(string instruction)
    {
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nLD     SM0.1\r\n{instruction}\r\nEND_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK VALVES:SBR0\r\n{Empty}END_SUBROUTINE_BLOCK\r\n");

        found.Refusals.Should().BeEmpty();
    }

    [Fact]
    public void Check_SubroutineTwice_RefusedAtTheSecond()
    {
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\n{Empty}END_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK A:SBR0\r\n{Empty}END_SUBROUTINE_BLOCK\r\nSUBROUTINE_BLOCK B:SBR0\r\n{Empty}END_SUBROUTINE_BLOCK\r\n");

        found.Refusals.Select(r => r.ToString()).Should().Equal("line 9: AWL014 SBR_0 is defined twice in the file");
    }

    [Fact]
    public void Check_BlockWithoutNetwork_WarnedAsProtected()
    {
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\n{Empty}END_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK PWM_INIT:SBR3\r\nBEGIN\r\nEND_SUBROUTINE_BLOCK\r\n");

        found.Refusals.Should().BeEmpty();
        found.Warnings.Should().ContainSingle().Which.ToString().Should().StartWith("line 5: AWL015 PWM_INIT (SBR3) is password-protected: Micro/WIN exports it without its code");
    }

    [Fact]
    public void Check_BlockAsMicroWinExportsAProtectedPou_WarnedAsProtected()
    {
        // The form of Sebaasu/xk335b-scada 1_Transporte/4_Traduccion_Ladder.awl (MBUS_INIT, MBUS_SLAVE, Q0_0_Home ...).
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\n{Empty}END_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK MBUS_INIT:SBR7\r\nVAR_INPUT\r\nMode:BYTE;\r\nEND_VAR\r\nBEGIN\r\n"
            + "Network 1 // This POU is password-protected against editing and viewing.\r\n\r\nEND_SUBROUTINE_BLOCK\r\n");

        found.Warnings.Should().ContainSingle().Which.ToString().Should().StartWith("line 5: AWL015 MBUS_INIT (SBR7) is password-protected");
    }

    [Fact]
    public void Check_EmptyNetworkWithOtherTitle_IsNotProtected()
    {
        var found = Check($"ORGANIZATION_BLOCK MAIN:OB1\r\n{Empty}END_ORGANIZATION_BLOCK\r\nSUBROUTINE_BLOCK SPARE:SBR3\r\nBEGIN\r\nNetwork 1 // Network Title\r\nEND_SUBROUTINE_BLOCK\r\n");

        found.Warnings.Should().BeEmpty();
    }
}

using OperatorPanel.Core.Protocol;
using OperatorPanel.Simulator.Reference;
using static OperatorPanel.Simulator.Tests.Stl.StlTestPrograms;

namespace OperatorPanel.Simulator.Tests.Stl;

public sealed class StlPlcInstructionTests
{
    [Fact]
    public void LogicStack_AldOldLpsLrdLpp_GiveS7200Results()
    {
        var plc = OneScan(
            "LD     M0.0\nO      M0.1\nLD     M0.2\nO      M0.3\nALD\n=      Q0.0\n" +   // (0|1)&(0|0) = 0
            "LD     M0.1\nLD     M0.0\nOLD\nNOT\n=      Q0.1\n" +                       // !(1|0) = 0
            "LD     M0.1\nLPS\nA      M0.0\n=      Q0.2\nLRD\n=      Q0.3\nLPP\nAN     M0.0\n=      Q0.4",
            blocks: string.Empty);
        plc.Memory.M[0] = 0b0010;
        plc.RunUntil(plc.Now + TimeSpan.FromMilliseconds(2));

        plc.Memory.Q[0].Should().Be(0b11000);
    }

    [Fact]
    public void Eu_FiresOnlyOnTheScanOfTheRisingEdge()
    {
        var plc = Plc("LD     I0.0\nEU\nINCB   VB0");
        plc.RunUntil(TimeSpan.FromMilliseconds(5));
        plc.InputImage[0] = 1;
        plc.RunUntil(TimeSpan.FromMilliseconds(10));
        plc.InputImage[0] = 0;
        plc.RunUntil(TimeSpan.FromMilliseconds(15));

        plc.Memory.V[0].Should().Be(1);
    }

    [Theory]
    [InlineData("LDB<   VB0, 16#90", true)]   // bytes unsigned: 16#80 < 16#90
    [InlineData("LDW<   VW0, 0", true)]       // words signed: 16#80FF is negative
    [InlineData("LDD>=  VD0, 0", false)]
    [InlineData("LDB=   VB0, 128", true)]
    [InlineData("LDW<>  VW0, VW0", false)]
    public void Compare_UsesS7200Signedness(string compare, bool expected)
    {
        var plc = OneScan($"LD     SM0.1\nMOVW   16#80FF, VW0\nNetwork 2\n{compare}\n=      Q0.0");

        (plc.Memory.Q[0] == 1).Should().Be(expected);
    }

    [Fact]
    public void Arithmetic_SetsZeroOverflowNegativeFlags()
    {
        var plc = OneScan(
            "LD     SM0.0\nMOVW   32767, VW0\n+I     1, VW0\nMOVB   SMB1, VB10\n" +
            "MOVW   5, VW2\n-I     5, VW2\nMOVB   SMB1, VB11\n" +
            "MOVD   -7, VD4\n/D     2, VD4\nMOVB   SMB1, VB12\n" +
            "MOVB   255, VB8\nINCB   VB8\nMOVB   SMB1, VB13\n" +
            "MOVW   9, VW20\n/I     0, VW20\nMOVB   SMB1, VB14\n" +
            "MOVW   300, VW22\nITB    VW22, VB24\nMOVB   SMB1, VB15\n" +
            "MOVB   16#81, VB25\nSLB    VB25, 1\nMOVB   SMB1, VB16");

        var v = plc.Memory.V;
        (plc.Memory.ReadWord(ProtocolArea.V, 0), v[10]).Should().Be(((ushort)0x8000, (byte)0x06));
        (plc.Memory.ReadWord(ProtocolArea.V, 2), v[11]).Should().Be(((ushort)0, (byte)0x01));
        (plc.Memory.ReadDoubleWord(ProtocolArea.V, 4), v[12]).Should().Be((unchecked((uint)-3), (byte)0x04));
        (v[8], v[13] & 0x03).Should().Be(((byte)0, 0x03));
        (plc.Memory.ReadWord(ProtocolArea.V, 20), v[14] & 0x08).Should().Be(((ushort)9, 0x08));
        (v[24], v[15] & 0x02).Should().Be(((byte)0, 0x02));
        (v[25], v[16] & 0x03).Should().Be(((byte)0x02, 0x02));
    }

    [Fact]
    public void LogicAndMoves_GiveValues()
    {
        var plc = OneScan(
            "LD     SM0.0\nMOVB   16#F0, VB0\nANDB   16#3C, VB0\nMOVW   16#1234, VW2\nSWAP   VW2\nMOVB   16#0F, VB4\nINVB   VB4\n" +
            "MOVD   16#01020304, VD10\nBMB    VB10, VB20, 4\nXORW   16#FFFF, VW20\nBTI    VB4, VW30\nMOVW   -2, VW32\nITD    VW32, VD34");

        plc.Memory.V.AsSpan(0, 5).ToArray().Should().Equal(0x30, 0, 0x34, 0x12, 0xF0);
        plc.Memory.V.AsSpan(20, 4).ToArray().Should().Equal(0xFE, 0xFD, 3, 4);
        plc.Memory.ReadWord(ProtocolArea.V, 30).Should().Be(0xF0);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 34).Should().Be(0xFFFFFFFE);
    }

    [Fact]
    public void Moves_AsciiConstants_GiveOneBytePerCharacter()
    {
        var plc = OneScan("LD     SM0.0\nMOVB   'A', VB0\nMOVW   'OK', VW2\nMOVD   'STOP', VD4");

        plc.Memory.V.AsSpan(0, 8).ToArray().Should().Equal(0x41, 0, 0x4F, 0x4B, 0x53, 0x54, 0x4F, 0x50);
    }

    [Fact]
    public void Ath_IllegalCharacterAndOddLength_FollowTheManual()
    {
        // C233-01 example: ATH VB30, VB40, 3 with 33 45 41 gives 3E, A(unchanged nibble).
        var plc = OneScan(
            "LD     SM0.0\nMOVB   16#33, VB30\nMOVB   16#45, VB31\nMOVB   16#41, VB32\nMOVB   16#07, VB41\n" +
            "ATH    VB30, VB40, 3\nMOVB   SMB1, VB50\nMOVB   16#61, VB33\nATH    VB32, VB44, 2\nMOVB   SMB1, VB51\n" +
            "MOVW   16#9A0F, VW60\nHTA    VB60, VB70, 3");

        plc.Memory.V.AsSpan(40, 2).ToArray().Should().Equal(0x3E, 0xA7);
        (plc.Memory.V[50] & 0x80, plc.Memory.V[51] & 0x80).Should().Be((0, 0x80));
        plc.Memory.V.AsSpan(70, 3).ToArray().Should().Equal((byte)'9', (byte)'A', (byte)'0');
    }

    [Fact]
    public void ForNextAndJumps_LoopAndSkip()
    {
        var plc = OneScan(
            "LD     SM0.0\nFOR    VW0, 1, 5\nNetwork 2\nLD     SM0.0\n+I     VW0, VW10\nNetwork 3\nNEXT\n" +
            "Network 4\nLD     SM0.0\nJMP    7\nNetwork 5\nLD     SM0.0\nMOVB   1, VB20\nNetwork 6\nLBL    7\n" +
            "Network 7\nLD     SM0.0\nFOR    VW30, 3, 2\nNetwork 8\nLD     SM0.0\nINCB   VB21\nNetwork 9\nNEXT");

        plc.Memory.ReadWord(ProtocolArea.V, 10).Should().Be(15);
        plc.Memory.ReadWord(ProtocolArea.V, 0).Should().Be(6);
        (plc.Memory.V[20], plc.Memory.V[21]).Should().Be((0, 0));
    }

    [Fact]
    public void Call_PassesParametersThroughLMemory()
    {
        const string sbr =
            "SUBROUTINE_BLOCK ADD:SBR0\r\nVAR_INPUT\r\nflag:BOOL;\r\na:WORD;\r\nEND_VAR\r\nVAR_IN_OUT\r\nacc:WORD;\r\nEND_VAR\r\n" +
            "VAR_OUTPUT\r\ncopy:BYTE;\r\nEND_VAR\r\nVAR\r\ntmp:WORD;\r\nEND_VAR\r\nBEGIN\r\nNetwork 1\r\n" +
            "LD     #flag\r\nMOVW   #a, #tmp\r\n+I     #tmp, #acc\r\nMOVB   LB1, #copy\r\nCRET\r\nNetwork 2\r\nLD     SM0.0\r\nMOVB   99, VB9\r\n" +
            "END_SUBROUTINE_BLOCK\r\n";
        var plc = OneScan("LD     SM0.0\nMOVW   16#0102, VW0\nMOVW   10, VW2\nCALL   ADD, SM0.0, VW0, VW2, VB4\nCALL   SBR_0, M0.0, 1, VW2, VB5", sbr);

        // First call: flag on, adds and CRET returns early. Second call: flag off, no add, the second network runs.
        plc.Memory.ReadWord(ProtocolArea.V, 2).Should().Be(10 + 0x0102);
        (plc.Memory.V[4], plc.Memory.V[9]).Should().Be((0x01, 99));
        plc.InstructionsIn("ADD").Should().Be(5 + 7);
    }

    [Fact]
    public void Indirect_ReadsAndWritesThroughPointers()
    {
        var plc = OneScan(
            "LD     SM0.0\nMOVD   &VB100, AC1\nMOVB   16#AB, *AC1\nINCD   AC1\nMOVW   16#CDEF, *AC1\nMOVD   &VB100, VD10\nMOVD   *VD10, VD20");

        plc.Memory.V.AsSpan(100, 3).ToArray().Should().Equal(0xAB, 0xCD, 0xEF);
        plc.Memory.ReadDoubleWord(ProtocolArea.V, 20).Should().Be(0xABCDEF00);
    }

    [Fact]
    public void Indirect_OutsideTheArea_StopsTheCpuWithAFault()
    {
        var plc = Plc("LD     SM0.0\nMOVD   &VB8191, AC1\nMOVW   1, *AC1");
        plc.RunUntil(TimeSpan.FromMilliseconds(5));

        plc.Mode.Should().Be(OperatingMode.Stop);
        plc.Fault!.Code.Should().Be("IndirectAddress");
        plc.Fault.Line.Should().Be(6);
    }
}

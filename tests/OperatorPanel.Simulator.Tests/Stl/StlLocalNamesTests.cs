using static OperatorPanel.Simulator.Tests.Stl.StlTestPrograms;

namespace OperatorPanel.Simulator.Tests.Stl;

/// <summary>
/// Local names are case-sensitive: the Siemens motion wizard's Q0_0_Home, as a real export holds it, declares
/// tmp_b:BOOL and tmp_B:BYTE in one block (docs/awl-exports.md).
/// </summary>
public sealed class StlLocalNamesTests
{
    [Fact]
    public void Call_LocalsDifferingOnlyInCase_AreTwoVariables()
    {
        const string sbr =
            "SUBROUTINE_BLOCK HOME:SBR0\r\nVAR\r\ntmp_b:BOOL;\r\ntmp_B:BYTE;\r\nEND_VAR\r\nBEGIN\r\nNetwork 1\r\n" +
            "LD     SM0.0\r\n=      #tmp_b\r\nMOVB   16#5A, #tmp_B\r\nLD     #tmp_b\r\n=      V10.0\r\nMOVB   #tmp_B, VB11\r\n" +
            "END_SUBROUTINE_BLOCK\r\n";

        var plc = OneScan("LD     SM0.0\nCALL   HOME", sbr);

        (plc.Memory.V[10], plc.Memory.V[11]).Should().Be((0x01, 0x5A));
    }
}

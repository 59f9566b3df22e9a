using static OperatorPanel.Stl.Instructions.StlOperands;

namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    private static IEnumerable<StlInstructionSpec> BitLogic()
    {
        foreach (var contact in (string[])["LD", "LDN", "A", "AN", "O", "ON"])
        {
            yield return Entry(contact, StlInstructionGroup.BitLogic, StlSources.Contacts, BitIn());
        }

        var input = new StlOperandSpec("bit", StlDataType.Bool, StlOperandKinds.I, StlAccess.Read);
        foreach (var contact in (string[])["LDI", "LDNI", "AI", "ANI", "OI", "ONI"])
        {
            yield return Entry(contact, StlInstructionGroup.BitLogic, StlSources.ImmediateContacts, input);
        }

        foreach (var stackOp in (string[])["NOT", "EU", "ED", "ALD", "OLD", "LPS", "LRD", "LPP", "AENO"])
        {
            yield return Entry(stackOp, StlInstructionGroup.BitLogic, StlSources.LogicStack);
        }

        yield return Entry("LDS", StlInstructionGroup.BitLogic, StlSources.LogicStack, Number("N", StlDataType.Byte, 1, 8));
        yield return Entry("=", StlInstructionGroup.BitLogic, StlSources.Coils, BitOut());
        yield return Entry("S", StlInstructionGroup.BitLogic, StlSources.Coils, BitOut("S_BIT").Widened(StlExtent.Count), Count());
        yield return Entry("R", StlInstructionGroup.BitLogic, StlSources.Coils, BitOut("S_BIT").Widened(StlExtent.Count), Count());
        var output = new StlOperandSpec("bit", StlDataType.Bool, StlOperandKinds.Q, StlAccess.Write);
        yield return Entry("=I", StlInstructionGroup.BitLogic, StlSources.ImmediateCoils, output);
        yield return Entry("SI", StlInstructionGroup.BitLogic, StlSources.ImmediateCoils, output.Widened(StlExtent.Count), Count());
        yield return Entry("RI", StlInstructionGroup.BitLogic, StlSources.ImmediateCoils, output.Widened(StlExtent.Count), Count());
        yield return Entry("NOP", StlInstructionGroup.BitLogic, StlSources.Nop, Number("N", StlDataType.Byte, 0, 255));
    }
}

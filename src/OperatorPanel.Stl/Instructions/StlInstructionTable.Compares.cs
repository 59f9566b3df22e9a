namespace OperatorPanel.Stl.Instructions;

public static partial class StlInstructionTable
{
    /// <summary>The STL relations of the compare contacts; "==" is LAD's way of writing "=", not STL's.</summary>
    public static readonly string[] Relations = ["=", "<>", "<", "<=", ">", ">="];

    /// <summary>LDB=, AW&lt;&gt;, OD&gt;=, LDR&lt;, AS=: form LD/A/O, width B (unsigned), W, D (signed), R (real), S (string; = and &lt;&gt; only).</summary>
    private static IEnumerable<StlInstructionSpec> Compares()
    {
        (char Width, Func<string, StlOperandSpec> Operand, StlFirmware Firmware)[] widths =
        [
            ('B', name => StlOperands.ByteIn(name), StlFirmware.All),
            ('W', name => StlOperands.WordIn(name), StlFirmware.All),
            ('D', name => StlOperands.DWordIn(name), StlFirmware.All),
            ('R', StlOperands.RealIn, StlFirmware.All),
            ('S', name => name == "IN1" ? StlOperands.StringIn(name) : StlOperands.StringArea(name, StlAccess.Read), StlFirmware.Version2),
        ];
        foreach (var form in (string[])["LD", "A", "O"])
        {
            foreach (var (width, operand, firmware) in widths)
            {
                foreach (var relation in width == 'S' ? Relations[..2] : Relations)
                {
                    yield return Entry($"{form}{width}{relation}", StlInstructionGroup.Compare,
                        width == 'S' ? StlSources.StringCompare : StlSources.Compare, operand("IN1"), operand("IN2")) with
                    {
                        Firmware = firmware,
                    };
                }
            }
        }
    }
}

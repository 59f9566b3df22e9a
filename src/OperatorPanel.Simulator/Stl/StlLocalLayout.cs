using OperatorPanel.Stl;

namespace OperatorPanel.Simulator.Stl;

/// <summary>
/// Places a block's locals in its 64 bytes of L memory as Micro/WIN does: in table order (IN, IN_OUT, OUT, then
/// TEMP), BOOLs packed into the bits of one byte, every other type starting at the next whole byte (facts doc
/// section 1: 64 bytes of L per POU).
/// </summary>
internal static class StlLocalLayout
{
    public static Dictionary<string, (StlLoc Loc, int Bytes, bool IsBit)> Place(
        StlBlock block, int lBytes, ICollection<AwlDiagnostic> diagnostics)
    {
        // Case-sensitive: the Siemens motion wizard's Q0_0_Home declares tmp_b:BOOL and tmp_B:BYTE (docs/awl-exports.md).
        var locals = new Dictionary<string, (StlLoc, int, bool)>(StringComparer.Ordinal);
        var offset = 0;
        var bitByte = -1;
        var bit = 8;
        foreach (var variable in block.Source.Variables.OrderBy(v => v.Section))
        {
            if (block.Kind != AwlBlockKind.Subroutine && variable.Section != AwlVariableSection.Temp)
            {
                diagnostics.Add(new AwlDiagnostic(variable.Line, $"#{variable.Name}: only a subroutine takes parameters; use VAR in {block.Name}"));
            }

            var bytes = BytesOf(variable.Type);
            if (bytes is null)
            {
                diagnostics.Add(new AwlDiagnostic(variable.Line, $"#{variable.Name}: type {variable.Type} is not implemented by the simulator"));
                continue;
            }

            StlLoc loc;
            if (bytes == 0)
            {
                if (bit == 8 || bitByte < 0)
                {
                    (bitByte, bit, offset) = (offset, 0, offset + 1);
                }

                loc = new StlLoc { Kind = StlLocKind.Local, Offset = bitByte, Bit = bit++ };
            }
            else
            {
                bitByte = -1;
                loc = new StlLoc { Kind = StlLocKind.Local, Offset = offset };
                offset += bytes.Value;
            }

            if (offset > lBytes)
            {
                diagnostics.Add(new AwlDiagnostic(variable.Line, $"#{variable.Name} does not fit in the {lBytes} bytes of L memory of {block.Name}"));
            }

            if (!locals.TryAdd(variable.Name, (loc, bytes.Value, bytes == 0)))
            {
                diagnostics.Add(new AwlDiagnostic(variable.Line, $"#{variable.Name} is declared twice in {block.Name}"));
            }
            else if (variable.Section != AwlVariableSection.Temp)
            {
                block.Formals.Add((loc, bytes.Value, variable.Section, bytes == 0));
            }
        }

        return locals;
    }

    /// <summary>Bytes of a local type, 0 for BOOL, null for a type the simulator does not implement (STRING, ...).</summary>
    private static int? BytesOf(string type) => type switch
    {
        "BOOL" => 0,
        "BYTE" => 1,
        "WORD" or "INT" => 2,
        "DWORD" or "DINT" or "REAL" => 4,
        _ => null,
    };
}

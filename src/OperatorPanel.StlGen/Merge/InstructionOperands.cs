using System.Collections.Frozen;
using OperatorPanel.Core.Stl;

namespace OperatorPanel.StlGen.Merge;

/// <summary>
/// Which operand of each S7-200 STL mnemonic is written (STL writes OUT = OUT op IN, so the written operand is the
/// last one of moves, arithmetic and logic, the first of INC/DEC/INV/shifts/=/S/R), and which operands a count widens
/// (BMB/BMW/BMD IN, OUT, N; FILL IN, OUT, N; ATH/HTA IN, OUT, LEN; S/R bit, N; SHRB DATA, S_BIT, N). Mnemonics not
/// listed only read their operands (loads, compares, ATCH, XMT, CALL without parameters).
/// </summary>
internal static class InstructionOperands
{
    private static readonly FrozenDictionary<string, int> WrittenIndex = Build();

    /// <summary>Count operand index and, per widened operand, the elements for a count n (ATH reads n characters, writes (n+1)/2 bytes).</summary>
    private static readonly FrozenDictionary<string, (int CountIndex, (int Index, Func<long, long> Elements)[] Operands)> Counted =
        new Dictionary<string, (int, (int, Func<long, long>)[])>(StringComparer.Ordinal)
        {
            ["BMB"] = (2, [(0, n => n), (1, n => n)]),
            ["BMW"] = (2, [(0, n => n), (1, n => n)]),
            ["BMD"] = (2, [(0, n => n), (1, n => n)]),
            ["FILL"] = (2, [(1, n => n)]),
            ["ATH"] = (2, [(0, n => n), (1, n => (n + 1) / 2)]),
            ["HTA"] = (2, [(0, n => (n + 1) / 2), (1, n => n)]),
            ["S"] = (1, [(0, n => n)]),
            ["R"] = (1, [(0, n => n)]),
            ["SI"] = (1, [(0, n => n)]),
            ["RI"] = (1, [(0, n => n)]),
        }.ToFrozenDictionary(StringComparer.Ordinal);

    /// <summary>Every operand of <paramref name="instruction"/> that parses as an operand; CALL parameters via the callee's variable table.</summary>
    public static IEnumerable<OperandUse> Uses(AwlInstruction instruction, AwlProgram program)
    {
        var mnemonic = instruction.Mnemonic;
        var operands = instruction.Operands;
        var shiftRegister = mnemonic == "SHRB" && operands.Length == 3;
        var counted = shiftRegister ? (2, [(1, n => Math.Abs(n))]) : Counted.GetValueOrDefault(mnemonic);
        var written = shiftRegister ? 1 : WrittenIndex.GetValueOrDefault(mnemonic, -1);
        var calleeOutputs = mnemonic == "CALL" ? CallOutputs(instruction, program) : [];
        long? count = null;
        var countUnknown = false;
        if (counted.Operands is not null && counted.CountIndex < operands.Length)
        {
            countUnknown = !AwlOperand.TryParse(operands[counted.CountIndex], out var n, out _)
                || n.Kind != AwlOperandKind.Constant || n.ConstantKind != AwlConstantKind.Integer;
            count = countUnknown ? null : n!.Integer;
        }

        for (var i = 0; i < operands.Length; i++)
        {
            if (!AwlOperand.TryParse(operands[i], out var operand, out _))
            {
                continue;
            }

            var widened = counted.Operands?.FirstOrDefault(o => o.Index == i);
            var elements = widened?.Elements is { } f && count is { } c ? f(c) : 1;
            var isWritten = i == written || (i > 0 && calleeOutputs.Contains(i - 1));
            yield return new OperandUse(instruction, i, operand, isWritten, elements, widened?.Elements is not null && countUnknown);
        }
    }

    /// <summary>Parameter positions (0-based, after the block name) bound to VAR_IN_OUT or VAR_OUTPUT of the called block.</summary>
    private static HashSet<int> CallOutputs(AwlInstruction call, AwlProgram program)
    {
        var callee = call.Operands.Length > 0 ? program.Find(call.Operands[0]) : null;
        var parameters = callee?.Variables.Where(v => v.Section != AwlVariableSection.Temp).OrderBy(v => v.Section).ToList() ?? [];
        return [.. parameters.Select((v, i) => (v, i)).Where(p => p.v.Section != AwlVariableSection.Input).Select(p => p.i)];
    }

    private static FrozenDictionary<string, int> Build()
    {
        string[] first =
        [
            "=", "=I", "S", "R", "SI", "RI", "SWAP", "INCB", "INCW", "INCD", "DECB", "DECW", "DECD", "INVB", "INVW", "INVD",
            "SLB", "SRB", "SLW", "SRW", "SLD", "SRD",
            "RLB", "RRB", "RLW", "RRW", "RLD", "RRD", "BCDI", "IBCD", "FOR", "RCV", "TODR", "NETR", "PID",
        ];
        string[] second =
        [
            "MOVB", "MOVW", "MOVD", "MOVR", "BIR", "BMB", "BMW", "BMD", "FILL", "+I", "-I", "*I", "/I", "+D", "-D", "*D", "/D",
            "+R", "-R", "*R", "/R", "MUL", "DIV", "SQRT", "LN", "EXP", "SIN", "COS", "TAN", "ANDB", "ORB", "XORB", "ANDW", "ORW",
            "XORW", "ANDD", "ORD", "XORD", "BTI", "ITB", "ITD", "DTI", "DTR", "ROUND", "TRUNC", "ENCO", "DECO", "SEG", "ATH",
            "HTA", "ITA", "DTA", "RTA", "ATT", "FIFO", "LIFO", "SCPY", "SCAT", "ITS", "DTS", "RTS",
        ];
        string[] third = ["FND=", "FND<>", "FND<", "FND>", "STI", "STD", "STR"];
        return first.Select(m => KeyValuePair.Create(m, 0)).Concat(second.Select(m => KeyValuePair.Create(m, 1)))
            .Concat(third.Select(m => KeyValuePair.Create(m, 2))).Append(KeyValuePair.Create("SSCPY", 3))
            .ToFrozenDictionary(StringComparer.Ordinal);
    }
}

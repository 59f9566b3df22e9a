using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// Whether one classified operand is of a kind and size the table allows in one operand position. Symbols pass:
/// their address is in the symbol table, not in the text. Locals (#name) are L memory of the declared type.
/// </summary>
public static class StlOperandMatch
{
    /// <summary>Null when <paramref name="operand"/> fits <paramref name="spec"/>; otherwise why not, naming the operand.</summary>
    public static StlOperandRefusal? Check(StlOperandSpec spec, AwlOperand operand, AwlVariable? local = null)
    {
        ArgumentNullException.ThrowIfNull(spec);
        ArgumentNullException.ThrowIfNull(operand);
        return operand.Kind switch
        {
            AwlOperandKind.Address => CheckAddress(spec, operand),
            AwlOperandKind.Constant => StlConstantMatch.Check(spec, operand),
            AwlOperandKind.Pointer => Allowed(spec, StlOperandKinds.AddressOf, operand, "an address (&)"),
            AwlOperandKind.Indirect => Allowed(spec, IndirectKind(operand.Area), operand, "an indirect access"),
            AwlOperandKind.Local => CheckLocal(spec, operand, local),
            AwlOperandKind.Symbol => null,
        };
    }

    /// <summary>The kind flag of a memory area.</summary>
    public static StlOperandKinds KindOf(MemoryArea area) => area switch
    {
        MemoryArea.I => StlOperandKinds.I,
        MemoryArea.Q => StlOperandKinds.Q,
        MemoryArea.M => StlOperandKinds.M,
        MemoryArea.V => StlOperandKinds.V,
        MemoryArea.SM => StlOperandKinds.SM,
        MemoryArea.S => StlOperandKinds.S,
        MemoryArea.T => StlOperandKinds.T,
        MemoryArea.C => StlOperandKinds.C,
        MemoryArea.AI => StlOperandKinds.AI,
        MemoryArea.AQ => StlOperandKinds.AQ,
        MemoryArea.AC => StlOperandKinds.AC,
        MemoryArea.HC => StlOperandKinds.HC,
        MemoryArea.L => StlOperandKinds.L,
    };

    private static StlOperandKinds IndirectKind(MemoryArea holder) => holder switch
    {
        MemoryArea.V => StlOperandKinds.IndirectV,
        MemoryArea.L => StlOperandKinds.IndirectL,
        MemoryArea.AC => StlOperandKinds.IndirectAc,
        MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.SM or MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AI or MemoryArea.AQ or MemoryArea.HC =>
            throw new ArgumentOutOfRangeException(nameof(holder), holder, "a pointer is held in VD, LD or AC1-AC3"),
    };

    private static StlOperandRefusal? CheckAddress(StlOperandSpec spec, AwlOperand operand)
    {
        if (Allowed(spec, KindOf(operand.Area), operand, AreaWords(operand.Area)) is { } refusal)
        {
            return refusal;
        }

        // T, C, AC and HC take the size of the position (a timer's bit or value); other areas say their width.
        if (operand.Area is MemoryArea.T or MemoryArea.C or MemoryArea.AC or MemoryArea.HC)
        {
            return spec.Type is StlDataType.Timer or StlDataType.Counter && (operand.ByteOffset < spec.Min || operand.ByteOffset > spec.Max)
                ? new StlOperandRefusal(StlRefusalKind.OutOfRange, $"'{operand.Text}' is outside {spec.Name}'s range {spec.Min}-{spec.Max}")
                : null;
        }

        var bytes = operand.Width == AccessWidth.Bit ? 0 : operand.Width.ByteCount();
        return bytes == spec.Bytes ? null
            : new StlOperandRefusal(StlRefusalKind.Kind, $"'{operand.Text}' is a {SizeName(bytes)}; {spec.Name} is a {TypeName(spec)}");
    }

    private static StlOperandRefusal? CheckLocal(StlOperandSpec spec, AwlOperand operand, AwlVariable? local)
    {
        if (Allowed(spec, StlOperandKinds.L, operand, "a local variable") is { } refusal)
        {
            return refusal;
        }

        var bytes = local is null ? null : BytesOfType(local.Type);
        return bytes is null || bytes == spec.Bytes ? null
            : new StlOperandRefusal(StlRefusalKind.Kind, $"'{operand.Text}' is declared {local!.Type}; {spec.Name} is a {TypeName(spec)}");
    }

    private static StlOperandRefusal? Allowed(StlOperandSpec spec, StlOperandKinds kind, AwlOperand operand, string what) =>
        (spec.Kinds & kind) != 0 ? null
            : new StlOperandRefusal(StlRefusalKind.Kind, $"'{operand.Text}' ({what}) cannot be {spec.Name} ({TypeName(spec)}: {StlOperandKindsText.Describe(spec)})");

    /// <summary>Bytes of a variable table type: 0 for BOOL; null for a type the check does not size.</summary>
    public static int? BytesOfType(string type) => type switch
    {
        "BOOL" => 0,
        "BYTE" or "CHAR" => 1,
        "WORD" or "INT" => 2,
        "DWORD" or "DINT" or "REAL" => 4,
        _ => null,
    };

    private static string AreaWords(MemoryArea area) => area switch
    {
        MemoryArea.T => "a timer",
        MemoryArea.C => "a counter",
        MemoryArea.AC => "an accumulator",
        MemoryArea.HC => "a high-speed counter",
        MemoryArea.AI => "an analog input",
        MemoryArea.AQ => "an analog output",
        MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.V or MemoryArea.SM or MemoryArea.S or MemoryArea.L => $"{area} memory",
    };

    private static string SizeName(int bytes) => bytes switch
    {
        0 => "bit",
        1 => "byte",
        2 => "word",
        _ => "double word",
    };

    internal static string TypeName(StlOperandSpec spec) => spec.Type.ToString().ToUpperInvariant();
}

namespace OperatorPanel.Stl.Instructions;

/// <summary>
/// Constants against one operand position: integers in the type's (or the position's) range, reals only for REAL,
/// ASCII constants ('A', 'AB') as one byte per character, string constants ("text") only for STRING.
/// </summary>
internal static class StlConstantMatch
{
    public static StlOperandRefusal? Check(StlOperandSpec spec, AwlOperand operand)
    {
        if ((spec.Kinds & StlOperandKinds.Constant) == 0)
        {
            return Refuse(spec, operand, $"a constant cannot be {spec.Name} ({StlOperandMatch.TypeName(spec)}: {StlOperandKindsText.Describe(spec)})");
        }

        return operand.ConstantKind switch
        {
            AwlConstantKind.Integer => CheckInteger(spec, operand),
            AwlConstantKind.Real => spec.Type == StlDataType.Real ? null : Refuse(spec, operand, $"a real constant cannot be {spec.Name} ({StlOperandMatch.TypeName(spec)})"),
            AwlConstantKind.Ascii => spec.Type == StlDataType.String || (spec.Bytes > 0 && operand.Name.Length <= spec.Bytes && spec.Type != StlDataType.Real) ? null
                : Refuse(spec, operand, $"an ASCII constant of {operand.Name.Length} character(s) does not fit {spec.Name} ({StlOperandMatch.TypeName(spec)})"),
            AwlConstantKind.String => spec.Type == StlDataType.String ? null : Refuse(spec, operand, $"a string constant cannot be {spec.Name} ({StlOperandMatch.TypeName(spec)})"),
        };
    }

    private static StlOperandRefusal? CheckInteger(StlOperandSpec spec, AwlOperand operand)
    {
        if (spec.Type == StlDataType.Real)
        {
            return Refuse(spec, operand, $"{spec.Name} is a REAL; write the constant with a decimal point ({operand.Integer}.0)");
        }

        var (min, max) = (spec.Min, spec.Max) switch
        {
            ({ } low, { } high) => (low, high),
            _ => spec.Bytes switch
            {
                1 => (0L, 255L),
                2 => (short.MinValue, ushort.MaxValue),
                _ => (int.MinValue, (long)uint.MaxValue),
            },
        };
        return operand.Integer >= min && operand.Integer <= max ? null
            : new StlOperandRefusal(StlRefusalKind.OutOfRange, $"'{operand.Text}' is outside {spec.Name}'s range {min}-{max}");
    }

    private static StlOperandRefusal Refuse(StlOperandSpec spec, AwlOperand operand, string why) =>
        new(StlRefusalKind.Kind, $"'{operand.Text}': {why}");
}

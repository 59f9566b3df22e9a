using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Stl;

public sealed partial record AwlOperand
{
    /// <summary>Numbered areas the panel's <see cref="PlcAddress"/> does not read: AC0, HC0, T37, C5.</summary>
    private static readonly (string Prefix, MemoryArea Area, AccessWidth Width)[] Numbered =
    [
        ("AC", MemoryArea.AC, AccessWidth.DoubleWord),
        ("HC", MemoryArea.HC, AccessWidth.DoubleWord),
        ("T", MemoryArea.T, AccessWidth.Word),
        ("C", MemoryArea.C, AccessWidth.Word),
    ];

    private static bool TryAddress(string input, [NotNullWhen(true)] out AwlOperand? operand, out string? error)
    {
        var upper = input.ToUpperInvariant();
        foreach (var (prefix, area, width) in Numbered)
        {
            if (upper.StartsWith(prefix, StringComparison.Ordinal) && upper.Length > prefix.Length
                && upper[prefix.Length..].All(char.IsAsciiDigit))
            {
                return TryNumbered(input, upper[prefix.Length..], area, width, out operand, out error);
            }
        }

        // L is not an area the panel addresses, so read it as V and put L back: LB4, LW0, LD8, L0.3.
        var isLocal = upper.StartsWith('L');
        if (!PlcAddress.TryParse(isLocal ? "V" + input[1..] : input, out var address, out var addressError))
        {
            operand = null;
            error = isLocal ? addressError.Message.Replace("'V", "'L", StringComparison.Ordinal) : addressError.Message;
            return false;
        }

        error = null;
        operand = new AwlOperand
        {
            Kind = AwlOperandKind.Address,
            Text = input,
            Area = isLocal ? MemoryArea.L : address.Area,
            Width = address.Width,
            ByteOffset = address.ByteOffset,
            Bit = address.Bit,
        };
        return true;
    }

    private static bool TryNumbered(
        string input, string digits, MemoryArea area, AccessWidth width, out AwlOperand? operand, out string? error)
    {
        operand = null;
        if (digits.Length > 5 || !int.TryParse(digits, NumberStyles.None, CultureInfo.InvariantCulture, out var number))
        {
            error = $"'{input}': the number is too large";
            return false;
        }

        error = null;
        operand = new AwlOperand { Kind = AwlOperandKind.Address, Text = input, Area = area, Width = width, ByteOffset = number };
        return true;
    }
}

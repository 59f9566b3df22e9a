using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Stl;

public sealed partial record AwlOperand
{
    /// <summary>Classifies an operand text; never throws. The error names the text and what is wrong with it.</summary>
    public static bool TryParse(
        string? text, [NotNullWhen(true)] out AwlOperand? operand, [NotNullWhen(false)] out string? error)
    {
        operand = null;
        var input = (text ?? string.Empty).Trim();
        if (input.Length == 0)
        {
            error = "operand is empty";
            return false;
        }

        var colon = input.IndexOf(':', StringComparison.Ordinal);
        if (colon > 0 && input[0] is not ('\'' or '"'))
        {
            return TrySymbolWithAddress(input, colon, out operand, out error);
        }

        switch (input[0])
        {
            case '#':
                return TryLocal(input, out operand, out error);
            case '&':
                return TryPointer(input, out operand, out error);
            case '*':
                return TryIndirect(input, out operand, out error);
            case '\'' or '"':
                return TryString(input, out operand, out error);
            case '+' or '-' or (>= '0' and <= '9'):
                return TryNumber(input, out operand, out error);
            default:
                return TryAddressOrSymbol(input, out operand, out error);
        }
    }

    /// <summary>
    /// NAME:ADDRESS, the symbol with its address as Micro/WIN exports it when the editor shows both
    /// (<c>A P13a_Rot_Des:M2.0</c>, Sebaasu/xk335b-scada 1_Transporte/4_Traduccion_Ladder.awl line 474; the papers' listings
    /// print <c>#XORCODE:LB6</c> and <c>RCV BUFFER:VB60,0</c>, seeds 003 and 004): the address is the operand, the name
    /// is kept for messages. A pointer or indirect access puts its &amp; or * before the name (&amp;Buffer:VB100).
    /// </summary>
    private static bool TrySymbolWithAddress(string input, int colon, out AwlOperand? operand, out string? error)
    {
        operand = null;
        var prefix = input[0] is '&' or '*' ? input[..1] : string.Empty;
        var name = input[prefix.Length..colon].Trim();
        var address = input[(colon + 1)..].Trim();
        var bareName = name.StartsWith('#') ? name[1..] : name;
        if (!IsIdentifier(bareName))
        {
            error = $"'{input}': the symbol before ':' is written with letters, digits and _ (NAME:VB100)";
            return false;
        }

        if (!TryParse(prefix + address, out var target, out error) || target.Kind is not (AwlOperandKind.Address or AwlOperandKind.Pointer or AwlOperandKind.Indirect))
        {
            error = $"'{input}': after the symbol '{name}:' an address is expected ({error ?? $"'{address}' is not one"})";
            operand = null;
            return false;
        }

        operand = target with { Text = input, SymbolName = name };
        return true;
    }

    private static bool TryLocal(string input, out AwlOperand? operand, out string? error)
    {
        var name = input[1..];
        operand = IsIdentifier(name) ? new AwlOperand { Kind = AwlOperandKind.Local, Text = input, Name = name } : null;
        error = operand is null ? $"'{input}': a local is written #name (letters, digits, _)" : null;
        return operand is not null;
    }

    private static bool TryPointer(string input, out AwlOperand? operand, out string? error)
    {
        operand = null;
        if (!TryAddress(input[1..], out var target, out error))
        {
            error = $"'{input}': {error}";
            return false;
        }

        // MOVD IN takes &VB, &IB, &QB, &MB, &SB, &SMB, &T, &C, &AIW, &AQW (docs/stl-instructions.md, MOVD).
        if (target.Width != AccessWidth.Byte && target.Area is not (MemoryArea.T or MemoryArea.C or MemoryArea.AI or MemoryArea.AQ))
        {
            error = $"'{input}': a pointer takes the address of a byte (&VB100), a timer, a counter or an analog word (&AIW0)";
            return false;
        }

        operand = target with { Kind = AwlOperandKind.Pointer, Text = input };
        return true;
    }

    private static bool TryIndirect(string input, out AwlOperand? operand, out string? error)
    {
        operand = null;
        if (!TryAddress(input[1..], out var holder, out error))
        {
            error = $"'{input}': {error}";
            return false;
        }

        var isHolder = holder.Area switch
        {
            MemoryArea.V or MemoryArea.L => holder.Width == AccessWidth.DoubleWord,
            MemoryArea.AC => holder.ByteOffset is >= 1 and <= 3,
            MemoryArea.I or MemoryArea.Q or MemoryArea.M or MemoryArea.SM or MemoryArea.S or MemoryArea.T or MemoryArea.C or MemoryArea.AI or MemoryArea.AQ or MemoryArea.HC => false,
        };
        if (!isHolder)
        {
            error = $"'{input}': a pointer is read from VD, LD or AC1-AC3 (*VD10, *LD4, *AC1)";
            return false;
        }

        operand = holder with { Kind = AwlOperandKind.Indirect, Text = input };
        return true;
    }

    private static bool TryString(string input, out AwlOperand? operand, out string? error)
    {
        operand = null;
        if (input.Length < 2 || input[^1] != input[0])
        {
            error = $"'{input}': the string has no closing quote";
            return false;
        }

        error = null;
        var characters = input[1..^1];
        var ascii = input[0] == '\'';
        operand = new AwlOperand
        {
            Kind = AwlOperandKind.Constant,
            Text = input,
            ConstantKind = ascii ? AwlConstantKind.Ascii : AwlConstantKind.String,
            Name = characters,
            Integer = ascii && characters.Length <= 4 ? characters.Aggregate(0L, (value, c) => (value * 256) + (c & 0xFF)) : 0,
        };
        return true;
    }

    private static bool TryNumber(string input, out AwlOperand? operand, out string? error)
    {
        operand = null;
        error = null;
        var negative = input[0] == '-';
        var body = input[0] is '+' or '-' ? input[1..] : input;
        if (TryRadix(body, out var value))
        {
            operand = IntegerConstant(input, negative ? -value : value);
            return true;
        }

        if ((body.Contains('.', StringComparison.Ordinal) || body.Contains('E', StringComparison.OrdinalIgnoreCase))
            && double.TryParse(input, NumberStyles.Float, CultureInfo.InvariantCulture, out var real))
        {
            operand = new AwlOperand { Kind = AwlOperandKind.Constant, Text = input, ConstantKind = AwlConstantKind.Real, Real = real };
            return true;
        }

        error = $"'{input}': not a number (write 100, -5, 16#3C, 2#1010 or 1.5)";
        return false;
    }

    /// <summary>Decimal, 16#hex or 2#binary digits; at most 32 bits of magnitude.</summary>
    private static bool TryRadix(string body, out long value)
    {
        var (radix, digits) = body.StartsWith("16#", StringComparison.Ordinal) ? (16, body[3..])
            : body.StartsWith("2#", StringComparison.Ordinal) ? (2, body[2..])
            : (10, body);
        value = 0;
        if (digits.Length == 0)
        {
            return false;
        }

        foreach (var c in digits)
        {
            var digit = char.IsAsciiDigit(c) ? c - '0' : char.IsAsciiHexDigit(c) ? char.ToUpperInvariant(c) - 'A' + 10 : 99;
            if (digit >= radix)
            {
                return false;
            }

            value = (value * radix) + digit;
            if (value > uint.MaxValue)
            {
                return false;
            }
        }

        return true;
    }

    private static AwlOperand IntegerConstant(string text, long value) =>
        new() { Kind = AwlOperandKind.Constant, Text = text, ConstantKind = AwlConstantKind.Integer, Integer = value };

    private static bool TryAddressOrSymbol(string input, out AwlOperand? operand, out string? error)
    {
        if (TryAddress(input, out var address, out error))
        {
            operand = address;
            return true;
        }

        // A name that is not an address (OP_RX, INT_0, SBR_3) is a block or symbol name; so are SBR6 and INT0, the
        // numeric POU references exports write (CALL SBR6, ATCH INT0, 10); "M10.8" is a bad address.
        if (IsIdentifier(input) && (!LooksLikeAddress(input) || IsPouNumber(input)))
        {
            error = null;
            operand = new AwlOperand { Kind = AwlOperandKind.Symbol, Text = input, Name = input };
            return true;
        }

        operand = null;
        error = $"'{input}': {error}";
        return false;
    }

    private static bool LooksLikeAddress(string input)
    {
        var letters = 0;
        while (letters < input.Length && char.IsAsciiLetter(input[letters]))
        {
            letters++;
        }

        return letters is > 0 and <= 3 && letters < input.Length && input[letters..].All(char.IsAsciiDigit);
    }

    /// <summary>SBRn or INTn: a subroutine or interrupt routine by number.</summary>
    public static bool IsPouNumber(string text) =>
        (text.StartsWith("SBR", StringComparison.OrdinalIgnoreCase) || text.StartsWith("INT", StringComparison.OrdinalIgnoreCase))
        && text.Length > 3 && text.Length <= 6 && text[3..].All(char.IsAsciiDigit);

    /// <summary>
    /// Letters, digits and _, not starting with a digit. Letters are those of the file's encoding as decoded
    /// (<see cref="AwlSource"/>: umlauts of a 1252 export, Chinese of a GBK one), and the characters 128-255 of a text
    /// read one character per byte (a caller that did not decode it).
    /// </summary>
    internal static bool IsIdentifier(string text) =>
        text.Length > 0 && IsNameLetter(text[0]) && text.All(c => IsNameLetter(c) || char.IsAsciiDigit(c));

    private static bool IsNameLetter(char c) => char.IsAsciiLetter(c) || c == '_' || c is >= '\u0080' and <= '\u00FF' || (c > '\u00FF' && char.IsLetter(c));
}

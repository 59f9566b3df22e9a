using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Stl;

/// <summary>The line-by-line state machine behind <see cref="AwlParser"/>: outside a block, in its header, in a variable table, in its body.</summary>
internal sealed class AwlReader
{
    private static readonly (string Open, string Close, AwlBlockKind Kind, string Prefix)[] BlockWords =
    [
        ("ORGANIZATION_BLOCK", "END_ORGANIZATION_BLOCK", AwlBlockKind.OrganizationBlock, "OB"),
        ("SUBROUTINE_BLOCK", "END_SUBROUTINE_BLOCK", AwlBlockKind.Subroutine, "SBR"),
        ("INTERRUPT_BLOCK", "END_INTERRUPT_BLOCK", AwlBlockKind.InterruptRoutine, "INT"),
    ];

    private AwlBlockBuilder? _block;

    public ImmutableArray<AwlBlock>.Builder Blocks { get; } = ImmutableArray.CreateBuilder<AwlBlock>();

    public ImmutableArray<AwlDiagnostic>.Builder Diagnostics { get; } = ImmutableArray.CreateBuilder<AwlDiagnostic>();

    public void Read(string raw, int line)
    {
        var (code, comment) = AwlParser.SplitComment(raw);
        if (code.Length == 0)
        {
            if (raw.TrimStart().StartsWith("//", StringComparison.Ordinal))
            {
                _block?.AddComment(comment);
            }

            return;
        }

        if (_block is null)
        {
            ReadOutside(code, line);
        }
        else if (IsClose(code, out var kind))
        {
            Close(kind, line);
        }
        else
        {
            ReadInBlock(_block, code, comment, line);
        }
    }

    public void Finish(int lastLine)
    {
        if (_block is not null)
        {
            Report(lastLine, $"block {_block.Name} has no {BlockWords[(int)_block.Kind].Close} line");
            Blocks.Add(_block.Build(lastLine));
            _block = null;
        }
    }

    private void ReadOutside(string code, int line)
    {
        var word = FirstWord(code);
        foreach (var (open, _, kind, prefix) in BlockWords)
        {
            if (string.Equals(word, open, StringComparison.OrdinalIgnoreCase))
            {
                Open(code[word.Length..].Trim(), kind, prefix, line);
                return;
            }
        }

        Report(line, $"'{code}' is outside any block; expected ORGANIZATION_BLOCK, SUBROUTINE_BLOCK or INTERRUPT_BLOCK");
    }

    private void Open(string header, AwlBlockKind kind, string prefix, int line)
    {
        var colon = header.IndexOf(':', StringComparison.Ordinal);
        var name = colon < 0 ? header : header[..colon].Trim();
        var id = colon < 0 ? header : header[(colon + 1)..].Trim();
        var number = 0;
        if (name.Length == 0
            || !id.StartsWith(prefix, StringComparison.OrdinalIgnoreCase)
            || !int.TryParse(id.AsSpan(prefix.Length), NumberStyles.None, CultureInfo.InvariantCulture, out number))
        {
            Report(line, $"'{header}' is not a block header of the form NAME:{prefix}n");
        }

        _block = new AwlBlockBuilder(kind, name.Length == 0 ? id : name, number, line, hasName: colon >= 0);
    }

    private void Close(AwlBlockKind kind, int line)
    {
        var block = _block!;
        if (kind != block.Kind)
        {
            Report(line, $"{BlockWords[(int)kind].Close} closes block {block.Name}, which is a {BlockWords[(int)block.Kind].Open}");
        }

        if (block.InVariables)
        {
            Report(line, $"block {block.Name}: a variable table has no END_VAR");
        }

        Blocks.Add(block.Build(line));
        _block = null;
    }

    private void ReadInBlock(AwlBlockBuilder block, string code, string comment, int line)
    {
        if (block.InBody)
        {
            ReadBody(block, code, comment, line);
        }
        else if (block.InVariables)
        {
            ReadVariable(block, code, comment, line);
        }
        else
        {
            ReadHeader(block, code, line);
        }
    }

    private void ReadHeader(AwlBlockBuilder block, string code, int line)
    {
        var word = FirstWord(code).ToUpperInvariant();
        if (code.StartsWith("TITLE", StringComparison.OrdinalIgnoreCase) && code[5..].TrimStart().StartsWith('='))
        {
            block.Title = code[(code.IndexOf('=', StringComparison.Ordinal) + 1)..].Trim();
        }
        else if (word == "BEGIN")
        {
            block.InBody = true;
        }
        else if (AwlBlockBuilder.SectionOf(word) is { } section)
        {
            block.OpenSection(section);
        }
        else
        {
            Report(line, $"'{code}' in the header of block {block.Name}; expected TITLE=, VAR_INPUT, VAR_IN_OUT, VAR_OUTPUT, VAR or BEGIN");
        }
    }

    private void ReadVariable(AwlBlockBuilder block, string code, string comment, int line)
    {
        if (string.Equals(code, "END_VAR", StringComparison.OrdinalIgnoreCase))
        {
            block.CloseSection();
            return;
        }

        var colon = code.IndexOf(':', StringComparison.Ordinal);
        var type = colon < 0 ? string.Empty : code[(colon + 1)..].Trim().TrimEnd(';').Trim().ToUpperInvariant();
        var name = colon < 0 ? string.Empty : code[..colon].Trim();
        if (name.Length == 0 || type.Length == 0 || !code.EndsWith(';'))
        {
            Report(line, $"'{code}' is not a variable entry of the form name:TYPE;");
            return;
        }

        block.AddVariable(name, type, comment, line);
    }

    private void ReadBody(AwlBlockBuilder block, string code, string comment, int line)
    {
        var word = FirstWord(code);
        if (string.Equals(word, "NETWORK", StringComparison.OrdinalIgnoreCase))
        {
            var number = code[word.Length..].Trim();
            if (!int.TryParse(number, NumberStyles.None, CultureInfo.InvariantCulture, out var n))
            {
                Report(line, $"'{code}': the network number is missing or not a number");
            }

            block.OpenNetwork(n, comment, line);
            return;
        }

        block.AddInstruction(new AwlInstruction(
            word.ToUpperInvariant(), AwlParser.SplitOperands(code[word.Length..]), comment, line), line);
    }

    private static bool IsClose(string code, out AwlBlockKind kind)
    {
        foreach (var (_, close, candidate, _) in BlockWords)
        {
            if (string.Equals(code, close, StringComparison.OrdinalIgnoreCase))
            {
                kind = candidate;
                return true;
            }
        }

        kind = default;
        return false;
    }

    private static string FirstWord(string code)
    {
        var end = code.IndexOfAny([' ', '\t']);
        return end < 0 ? code : code[..end];
    }

    private void Report(int line, string message) => Diagnostics.Add(new AwlDiagnostic(line, message));
}

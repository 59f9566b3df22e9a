using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Projects;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Symbols;
using OperatorPanel.StlGen;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// Reading the user's files for <c>stl run</c> and <c>generate --merge</c>: an exported program (its encoding detected,
/// <see cref="AwlSource"/>) and its symbol table (<c>--symbols</c>), whose unreadable lines are warnings naming them.
/// </summary>
internal static class AwlFiles
{
    public static bool TryRead(string path, [NotNullWhen(true)] out AwlSource? source, [NotNullWhen(false)] out string? error)
    {
        source = null;
        if (!AtomicFile.TryReadAll(path, HandlerPackage.MaxProgramBytes, out var bytes, out var reason))
        {
            error = $"{path}: {reason}";
            return false;
        }

        (source, error) = (AwlSource.Decode(bytes), null);
        return true;
    }

    public static bool TryReadSymbols(CliContext cli, string path, [NotNullWhen(true)] out AwlSymbolTable? table, [NotNullWhen(false)] out string? error)
    {
        table = null;
        if (!TryRead(path, out var source, out error))
        {
            return false;
        }

        table = AwlSymbolTable.Parse(source.Text);
        var name = Path.GetFileName(path);
        foreach (var rejected in table.Rejected)
        {
            cli.Error.WriteLine($"{name}:{rejected.Line}: warning: {rejected.Message}");
        }

        if (table.Count == 0)
        {
            (table, error) = (null, $"{path}: no symbol found; export the symbol table from Micro/WIN as text (symbol, address, comment, separated by tabs; a CSV file separated by semicolons or commas is read too)");
            return false;
        }

        return true;
    }
}

using System.CommandLine;
using System.CommandLine.Parsing;

namespace OperatorPanel.Cli;

/// <summary>
/// Says in plain words what is wrong with a command line System.CommandLine could not parse, for every verb at once:
/// its own messages name .NET types ("as expected type 'System.Nullable`1[System.Double]'") and come with the whole
/// help text, which hid the one line that mattered and was not JSON under --json.
/// </summary>
internal static class CommandLineErrors
{
    /// <summary>One message per problem, in the order System.CommandLine found them, each naming what the option or verb takes.</summary>
    public static IReadOnlyList<string> Describe(ParseResult parse)
    {
        var messages = new List<string>();
        var commandLevel = false;
        foreach (var error in parse.Errors)
        {
            var message = error.SymbolResult switch
            {
                ArgumentResult { Parent: OptionResult option } => OptionValue(option),
                OptionResult option => OptionValue(option),
                ArgumentResult argument => MissingArgument(argument),
                _ => null,
            };

            if (message is null)
            {
                // Unmatched tokens and a missing subcommand belong to the command: said once from the parse result
                // below, which knows which tokens and subcommands they are.
                commandLevel = true;
                continue;
            }

            Add(messages, message);
        }

        if (commandLevel)
        {
            var described = CommandProblems(parse).ToList();
            if (described.Count == 0)
            {
                // A kind of error not foreseen here: System.CommandLine's own words beat saying nothing.
                described.AddRange(parse.Errors.Where(e => e.SymbolResult is not (ArgumentResult or OptionResult)).Select(e => e.Message));
            }

            foreach (var message in described)
            {
                Add(messages, message);
            }
        }

        return messages;
    }

    /// <summary>Where to read what the verb takes: "see opanel watch --help".</summary>
    public static string Hint(ParseResult parse) => $"see {CommandPath(parse.CommandResult)} --help";

    private static void Add(List<string> messages, string message)
    {
        if (!messages.Contains(message, StringComparer.Ordinal))
        {
            messages.Add(message);
        }
    }

    private static string OptionValue(OptionResult result)
    {
        var option = result.Option;
        if (result.IdentifierToken is null)
        {
            // A required option left out: its description says what it is ("CPU model: 221, 222, 224, 224XP or 226").
            return $"{CommandPath(result.Parent as CommandResult)} needs {option.Name}{Described(option.Description)}";
        }

        var name = result.IdentifierToken.Value;
        var tokens = result.Tokens.Select(t => t.Value).ToList();
        if (Takes(option) is not { } takes)
        {
            return $"{name} needs a value{Described(option.Description)}";
        }

        return tokens.Count == 0 ? $"{name} needs a value: give {takes}" : $"{name} {string.Join(' ', tokens)}: give {takes}";
    }

    /// <summary>What an option's value type accepts, in words: "a number of seconds", "reference or stl"; null for text.</summary>
    private static string? Takes(Option option)
    {
        var type = option.ValueType;
        var many = type.IsArray;
        var element = Nullable.GetUnderlyingType(many ? type.GetElementType()! : type) ?? (many ? type.GetElementType()! : type);
        // An option whose unit is not in its name says it by its help name (--duration <seconds>).
        var unit = option.HelpName is { Length: > 0 } help ? $" of {help}" : "";
        if (element.IsEnum)
        {
            var names = Enum.GetNames(element).Select(n => n.ToLowerInvariant()).ToList();
            var choice = names.Count == 1 ? names[0] : $"{string.Join(", ", names[..^1])} or {names[^1]}";
            return many ? $"one or more of {choice}" : choice;
        }

        return element switch
        {
            _ when element == typeof(int) || element == typeof(long) => many ? $"whole numbers{unit}" : $"a whole number{unit}",
            _ when element == typeof(double) || element == typeof(decimal) => many ? $"numbers{unit}" : $"a number{unit}",
            _ when element == typeof(bool) => "true or false",
            _ => null,
        };
    }

    private static string MissingArgument(ArgumentResult result)
    {
        var argument = result.Argument;
        var name = argument.HelpName is { Length: > 0 } help ? help : argument.Name;
        var verb = CommandPath(result.Parent as CommandResult);
        // The arguments' descriptions run to several clauses (read's lists every format): the hint's --help has them.
        return result.Tokens.Count == 0
            ? argument.ValueType.IsArray ? $"{verb} needs at least one <{name}>" : $"{verb} needs its <{name}>"
            : $"{verb}: {string.Join(' ', result.Tokens.Select(t => t.Value))} is not a valid <{name}>";
    }

    private static IEnumerable<string> CommandProblems(ParseResult parse)
    {
        var command = parse.CommandResult;
        var verb = CommandPath(command);
        foreach (var token in parse.UnmatchedTokens)
        {
            yield return token.StartsWith('-') ? $"{verb} has no option {token}" : $"{verb} takes no argument '{token}'";
        }

        if (command.Command.Action is null && command.Command.Subcommands.Count > 0)
        {
            var names = command.Command.Subcommands.Where(c => !c.Hidden).Select(c => c.Name).ToList();
            var choice = names.Count == 1 ? names[0] : $"{string.Join(", ", names[..^1])} or {names[^1]}";
            yield return $"{verb} needs a command: {choice}";
        }
    }

    private static string Described(string? description) => description is { Length: > 0 } text ? $" ({text})" : "";

    /// <summary>"opanel bench plan": the verb as typed, from the root down.</summary>
    private static string CommandPath(CommandResult? command)
    {
        var names = new Stack<string>();
        for (SymbolResult? result = command; result is CommandResult c; result = c.Parent)
        {
            names.Push(c.Parent is null ? "opanel" : c.Command.Name);
        }

        return names.Count == 0 ? "opanel" : string.Join(' ', names);
    }
}

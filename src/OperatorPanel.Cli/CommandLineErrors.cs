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
        var unmatched = parse.UnmatchedTokens.ToList();
        var commands = command.Command.Subcommands.Where(c => !c.Hidden).Select(c => c.Name).ToList();
        var optionNames = OptionNames(command).ToList();
        var commandNamed = false;
        for (var i = 0; i < unmatched.Count; i++)
        {
            var token = unmatched[i];
            if (token.StartsWith('-'))
            {
                // A mistyped option's value would otherwise be a second problem ("takes no argument 'out'") that
                // the user did not make: it is named with its option.
                var value = i + 1 < unmatched.Count && !unmatched[i + 1].StartsWith('-') && FollowsInLine(parse, token, unmatched[i + 1])
                    ? unmatched[++i]
                    : null;
                var given = value is null ? "" : $" (given '{value}')";
                yield return $"{verb} has no option {token}{given}{Suggestion(token, optionNames)}";
            }
            else if (i == 0 && command.Command.Action is null && commands.Count > 0)
            {
                // What follows a mistyped command is its arguments and options: one problem, not several.
                commandNamed = true;
                yield return $"{verb} has no command '{token}'{Suggestion(token, commands)}";
                yield break;
            }
            else
            {
                yield return $"{verb} takes no argument '{token}'";
            }
        }

        if (command.Command.Action is null && commands.Count > 0 && !commandNamed)
        {
            var choice = commands.Count == 1 ? commands[0] : $"{string.Join(", ", commands[..^1])} or {commands[^1]}";
            yield return $"{verb} needs a command: {choice}";
        }
    }

    /// <summary>Whether <paramref name="value"/> came right after <paramref name="option"/> on the command line.</summary>
    private static bool FollowsInLine(ParseResult parse, string option, string value)
    {
        var tokens = parse.Tokens.Select(t => t.Value).ToList();
        var at = tokens.IndexOf(option);
        return at >= 0 && at + 1 < tokens.Count && tokens[at + 1] == value;
    }

    /// <summary>The options the command and its parents take (global ones too), by every name and alias.</summary>
    private static IEnumerable<string> OptionNames(CommandResult command)
    {
        for (SymbolResult? result = command; result is CommandResult c; result = c.Parent)
        {
            foreach (var option in c.Command.Options.Where(o => !o.Hidden && (o.Recursive || ReferenceEquals(c, command))))
            {
                yield return option.Name;
                foreach (var alias in option.Aliases)
                {
                    yield return alias;
                }
            }
        }
    }

    /// <summary>": did you mean --output?" for a name within two edits of one the command takes (or one it begins); else nothing.</summary>
    private static string Suggestion(string typed, IReadOnlyList<string> names)
    {
        var best = names
            .Where(n => n.Length > 1)
            .Select(n => (Name: n, Distance: EditDistance(typed.ToLowerInvariant(), n.ToLowerInvariant())))
            .Where(c => c.Distance <= Math.Max(1, Math.Min(2, typed.Length / 3)) || (typed.Length >= 3 && c.Name.StartsWith(typed, StringComparison.OrdinalIgnoreCase)))
            .OrderBy(c => c.Distance)
            .ThenBy(c => c.Name, StringComparer.Ordinal)
            .Select(c => c.Name)
            .Distinct()
            .Take(2)
            .ToList();
        return best.Count switch
        {
            0 => "",
            1 => $": did you mean {best[0]}?",
            _ => $": did you mean {best[0]} or {best[1]}?",
        };
    }

    /// <summary>Levenshtein distance, a transposition counted as one edit ("wacth" is one from "watch").</summary>
    private static int EditDistance(string a, string b)
    {
        var d = new int[a.Length + 1, b.Length + 1];
        for (var i = 0; i <= a.Length; i++)
        {
            d[i, 0] = i;
        }

        for (var j = 0; j <= b.Length; j++)
        {
            d[0, j] = j;
        }

        for (var i = 1; i <= a.Length; i++)
        {
            for (var j = 1; j <= b.Length; j++)
            {
                var cost = a[i - 1] == b[j - 1] ? 0 : 1;
                d[i, j] = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
                if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                {
                    d[i, j] = Math.Min(d[i, j], d[i - 2, j - 2] + 1);
                }
            }
        }

        return d[a.Length, b.Length];
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

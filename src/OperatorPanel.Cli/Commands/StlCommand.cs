using System.CommandLine;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel stl ...</c>: work with STL (.awl) programs offline; today <c>stl run</c> (<see cref="StlRunCommand"/>).</summary>
internal static class StlCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var command = new Command("stl", "Work with S7-200 STL programs (Micro/WIN .awl exports) offline");
        command.Subcommands.Add(StlRunCommand.Create(context));
        return command;
    }
}

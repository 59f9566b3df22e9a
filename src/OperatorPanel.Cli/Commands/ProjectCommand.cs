using System.CommandLine;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel project new|check</c>: create and check <c>.opproj</c> project files (one per production line).</summary>
internal static class ProjectCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var command = new Command("project", "Create and check .opproj project files (one JSON file per production line)");
        command.Subcommands.Add(ProjectNewCommand.Create(context));
        command.Subcommands.Add(ProjectCheckCommand.Create(context));
        return command;
    }
}

using System.CommandLine;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Commands;

/// <summary><c>opanel cpus</c>: every CPU profile with its areas and ranges.</summary>
internal static class CpusCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var command = new Command("cpus", "List the supported S7-200 CPUs with their memory areas, ranges and Freeport baud rates");
        command.SetAction(parse =>
        {
            var cli = context(parse);
            if (cli.Json)
            {
                cli.WriteJson(CpuProfiles.All.Select(CpuProfileView.From));
            }
            else
            {
                foreach (var profile in CpuProfiles.All)
                {
                    CpuProfileView.From(profile).WriteText(cli.Out);
                }
            }

            return ExitCodes.Ok;
        });
        return command;
    }
}

using System.CommandLine;
using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Cli.Commands;

/// <summary>
/// <c>opanel project new --cpu MODEL -o FILE</c>: writes a valid starter project, one station with every local
/// input and output of the CPU, for the technician to rename and extend.
/// </summary>
internal static class ProjectNewCommand
{
    public static Command Create(Func<ParseResult, CliContext> context)
    {
        var cpu = CpuOptions.Model();
        var revision = CpuOptions.Revision();
        var station = new Option<int>("--station")
        {
            Description = "RS-485 station address of the PLC, 1-126 (default 2, the S7-200 factory setting)",
            DefaultValueFactory = _ => 2,
        };
        var port = new Option<string>("--port") { Description = "Serial port of the PC (default COM1)", DefaultValueFactory = _ => "COM1" };
        var name = new Option<string?>("--name") { Description = "Project name (default: the file name)" };
        var output = new Option<string>("--output", "-o") { Description = "The .opproj file to write", Required = true };
        var force = new Option<bool>("--force") { Description = "Replace an existing file (the old one is kept as FILE.bak)" };
        var command = new Command("new", "Write a valid starter project for one CPU")
        {
            cpu, revision, station, port, name, output, force,
        };
        command.SetAction(parse =>
        {
            var cli = context(parse);
            if (!CpuOptions.TryResolve(parse.GetValue(cpu), parse.GetValue(revision), out var profile, out var cpuError))
            {
                return cli.Fail(ExitCodes.BadInput, cpuError);
            }

            if (!Station.TryCreate(parse.GetValue(station), out var address, out var stationError))
            {
                return cli.Fail(ExitCodes.BadInput, stationError);
            }

            var portName = parse.GetValue(port);
            if (string.IsNullOrWhiteSpace(portName))
            {
                return cli.Fail(ExitCodes.BadInput, "the serial port name is empty; write e.g. --port COM3 or --port /dev/ttyUSB0");
            }

            var file = parse.GetValue(output)!;
            if (File.Exists(file) && !parse.GetValue(force))
            {
                return cli.Fail(ExitCodes.BadInput, $"{file} already exists; add --force to replace it (the old file is kept as {file}.bak)");
            }

            var project = StarterProject.Create(parse.GetValue(name) ?? Path.GetFileNameWithoutExtension(file), profile, address, portName);
            // --name, --port and the file's name go into the project as they are: what check would refuse is not written.
            var problems = ProjectFile.Check(project);
            if (!problems.IsEmpty)
            {
                return cli.FailAll(ExitCodes.BadInput, [.. problems.Select(p => p.Message)], $"{file} not written");
            }

            if (!TryCreateFolder(file, out var folderError))
            {
                return cli.Fail(ExitCodes.BadInput, folderError);
            }

            if (!ProjectFile.TrySave(project, file, out var saveError))
            {
                return cli.Fail(ExitCodes.BadInput, $"{file}: {saveError}");
            }

            cli.Log.Information("Wrote starter project {File} for {Cpu}", file, profile.DisplayName);
            var summary = ProjectSummaryView.From(project);
            if (cli.Json)
            {
                cli.WriteJson(new { ok = true, file, project = summary });
            }
            else
            {
                cli.Out.WriteLine($"wrote {file}");
                summary.WriteText(cli.Out);
            }

            return ExitCodes.Ok;
        });
        return command;
    }

    /// <summary>A new project goes where it is asked to, its folder made first (<c>-o plant/line3.opproj</c>).</summary>
    private static bool TryCreateFolder(string file, [NotNullWhen(false)] out string? error)
    {
        var folder = Path.GetDirectoryName(Path.GetFullPath(file));
        error = null;
        if (folder is null || Directory.Exists(folder))
        {
            return true;
        }

        try
        {
            Directory.CreateDirectory(folder);
            return true;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            error = $"cannot create the folder {folder} for {Path.GetFileName(file)}: {ex.Message}";
            return false;
        }
    }
}

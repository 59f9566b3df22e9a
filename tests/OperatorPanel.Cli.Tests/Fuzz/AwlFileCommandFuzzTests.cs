using System.Runtime.CompilerServices;
using System.Text;
using System.Text.RegularExpressions;
using OperatorPanel.TestKit;

namespace OperatorPanel.Cli.Tests.Fuzz;

/// <summary>
/// <c>opanel stl run</c> and <c>opanel generate --merge</c> on mutated tests/StlCorpus programs (lines cut, tokens
/// inserted, NUL bytes, megabyte lines, truncations; seeded): exit 0, 1 or (generate) 2, and a refusal names the file
/// and line ("prog.awl:12: ...") in readable lines without control characters, never a stack trace.
/// </summary>
public sealed partial class AwlFileCommandFuzzTests : IDisposable
{
    private readonly string _folder = Directory.CreateTempSubdirectory("opanel-awl-fuzz-").FullName;

    [Fact]
    public void StlRunAndMerge_MutatedPrograms_ExitOneWithFileAndLineOrRun()
    {
        var random = new Random(226);
        var project = Path.Combine(_folder, "224-2.opproj");
        CliRunner.Run("project", "new", "--cpu", "224", "--station", "2", "--port", "COM1", "-o", project).ExitCode.Should().Be(0);
        var sources = Directory.GetFiles(CorpusFolder(), "*.awl").Order().ToArray();
        var failures = new List<string>();
        var refusals = 0;
        for (var i = 0; i < 24; i++)
        {
            var source = sources[i % sources.Length];
            var (text, how) = Mutate(File.ReadAllText(source, Encoding.Latin1), random, i);
            var path = Path.Combine(_folder, "prog.awl");
            File.WriteAllText(path, text, Encoding.Latin1);
            var because = $"{Path.GetFileName(source)}, {how}";

            var runs = new[]
            {
                (Refused: 1, Run: CliRunner.Run("stl", "run", path, "--cpu", "224", "--for", "100ms", "--print", "Q0.0")),
                (Refused: 2, Run: CliRunner.Run("generate", project, "-o", Path.Combine(_folder, "out"), "--merge", path)),
            };

            foreach (var (refused, (exit, _, error)) in runs)
            {
                refusals += exit == refused ? 1 : 0;
                if ((exit != 0 && exit != refused) || error.Contains("Exception", StringComparison.Ordinal) || error.Contains("   at ", StringComparison.Ordinal)
                    || error.Split('\n').Any(line => line.Length > 400 || line.Any(c => char.IsControl(c) && c is not ('\t' or '\r')))
                    || (exit == refused && !FileAndLine().IsMatch(error)))
                {
                    failures.Add($"{because}: exit {exit}: {error[..Math.Min(error.Length, 600)].Replace('\0', '@')}");
                }
            }
        }

        failures.Should().BeEmpty();
        refusals.Should().BeGreaterThan(10, "most mutations break the program");
    }

    public void Dispose() => Directory.Delete(_folder, recursive: true);

    /// <summary>The shared .awl mutation, and every sixth program a megabyte line as well (a pasted blob).</summary>
    private static (string Text, string How) Mutate(string text, Random random, int index)
    {
        var (mutated, how) = AwlMutator.Mutate(text, random);
        if (index % 6 != 5)
        {
            return (mutated, how);
        }

        var lines = mutated.Split('\n');
        var at = random.Next(lines.Length);
        lines[at] += new string('9', 1 << 20);
        return (string.Join('\n', lines), $"{how}, line {at + 1} got a megabyte");
    }

    private static string CorpusFolder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "StlCorpus"));

    [GeneratedRegex(@"prog\.awl:[0-9]+: |opanel: ")]
    private static partial Regex FileAndLine();
}

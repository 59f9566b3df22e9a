using System.Runtime.CompilerServices;
using System.Text;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;
using OperatorPanel.Simulator.Tests.Hosting;
using OperatorPanel.TestKit;

namespace OperatorPanel.Simulator.Tests.Fuzz;

/// <summary>
/// Mutated .awl text (the generated handler and every tests/StlCorpus program: lines cut or repeated, tokens inserted
/// or replaced, truncations, flipped characters, NUL bytes, megabyte lines) never makes the loader or a run of what
/// loaded throw: each problem is a diagnostic on a line of the file, short enough to read. Seeded per source.
/// </summary>
public sealed class AwlLoadFuzzTests
{
    private const int CasesPerSource = 80;

    private static readonly CpuProfile Cpu224 = CpuProfiles.For(CpuModel.Cpu224);

    public static TheoryData<string> Sources() =>
        ["Handler224Station2.awl", .. Directory.GetFiles(CorpusFolder(), "*.awl").Select(f => Path.GetFileName(f)).Order()];

    [Theory]
    [MemberData(nameof(Sources))]
    public void Load_MutatedSource_GivesShortLineDiagnosticsNeverThrows(string source)
    {
        var text = Text(source);
        var random = new Random(AwlMutator.Seed(source));
        var failures = new List<string>();
        for (var i = 0; i < CasesPerSource; i++)
        {
            var (mutated, how) = AwlMutator.Mutate(text, random);
            Check(mutated, $"{source} #{i} {how}", failures);
        }

        failures.Should().BeEmpty();
    }

    [Fact]
    public void Load_MegabyteLinesAndNulBytesInTheHandler_GiveShortLineDiagnostics()
    {
        var lines = Text("Handler224Station2.awl").Split('\n');
        var random = new Random(1024);
        var failures = new List<string>();
        for (var i = 0; i < 6; i++)
        {
            var at = random.Next(lines.Length);
            var huge = (string[])lines.Clone();
            huge[at] += new string(i % 2 == 0 ? '9' : '\0', 1 << 20);
            Check(string.Join('\n', huge), $"megabyte line {at + 1}", failures);
        }

        Check(new string('\0', 1 << 20), "a megabyte of NUL", failures);
        failures.Should().BeEmpty();
    }

    private static string Text(string source)
    {
        if (source.StartsWith("Handler", StringComparison.Ordinal))
        {
            using var stream = typeof(StlStations).Assembly.GetManifestResourceStream(source)!;
            using var reader = new StreamReader(stream, Encoding.Latin1);
            return reader.ReadToEnd();
        }

        return File.ReadAllText(Path.Combine(CorpusFolder(), source), Encoding.Latin1);
    }

    private static string CorpusFolder([CallerFilePath] string self = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(self)!, "..", "..", "StlCorpus"));

    private static void Check(string text, string because, List<string> failures)
    {
        var lineCount = text.Split('\n').Length;
        StlLoadResult result;
        try
        {
            result = StlProgramLoader.Load(text, Cpu224);
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            failures.Add($"{because}: load threw {ex.GetType().Name}: {ex.Message}");
            return;
        }

        foreach (var d in result.Diagnostics.Where(d => d.Line < 1 || d.Line > lineCount || d.Message.Length is 0 or > 300))
        {
            failures.Add($"{because}: diagnostic off the file or unreadable: line {d.Line}, {d.Message.Length} characters");
        }

        if (!result.Succeeded)
        {
            return;
        }

        try
        {
            // What loads runs: a fault stops the simulated CPU (StlFault), it never escapes as an exception.
            new StlRun(result.Program).Run(TimeSpan.FromMilliseconds(30), []);
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            failures.Add($"{because}: run threw {ex.GetType().Name}: {ex.Message}");
        }
    }
}

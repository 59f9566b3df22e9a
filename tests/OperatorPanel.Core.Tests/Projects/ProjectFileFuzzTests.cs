using System.Text;
using System.Text.Json.Nodes;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// Loading never throws, whatever the input: byte flips, truncations, binary files and every value of the sample
/// replaced by every JSON kind. A seeded Random keeps failures reproducible. Each test collects its failures and
/// asserts once, so thousands of inputs stay fast.
/// </summary>
public sealed class ProjectFileFuzzTests
{
    private const string Placeholder = "__fuzz__";

    private static readonly byte[] SampleBytes = Encoding.UTF8.GetBytes(SampleProject.Text);

    /// <summary>Replacement values: every JSON kind, edge numbers and awkward strings.</summary>
    private static readonly string[] Replacements =
    [
        "null", "true", "false", "0", "-1", "1.5", "1e400", "-99999999999999999999", "\"\"", "\" \"", "\"x\"",
        "\"\\u0000\"", "\"\\uDC00\"", "[]", "{}", "[[]]", "[{}]", "{\"a\":1}",
    ];

    [Fact]
    public void Parse_RandomByteFlips_NeverThrowsAndValidResultsRoundTrip()
    {
        var random = new Random(2013);
        var failures = new List<string>();
        for (var i = 0; i < 2000; i++)
        {
            var bytes = (byte[])SampleBytes.Clone();
            for (var flips = random.Next(1, 4); flips > 0; flips--)
            {
                bytes[random.Next(bytes.Length)] = (byte)random.Next(256);
            }

            var result = Parse(Encoding.UTF8.GetString(bytes), $"mutation {i}", failures);
            if (result is { Ok: true } && !ProjectFile.Parse(ProjectFile.Format(result.Project)).Ok)
            {
                failures.Add($"mutation {i}: loaded, but its saved form does not");
            }
        }

        failures.Should().BeEmpty();
    }

    [Fact]
    public void Load_RandomBinaryFiles_AreProblemsNeverExceptions()
    {
        using var folder = new TempFolder();
        var path = folder.File("fuzz.opproj");
        var random = new Random(62);
        var failures = new List<string>();
        for (var i = 0; i < 200; i++)
        {
            var bytes = new byte[random.Next(0, 300)];
            random.NextBytes(bytes);
            File.WriteAllBytes(path, bytes);
            try
            {
                if (ProjectFile.Load(path).Ok)
                {
                    failures.Add($"binary file {i} loaded");
                }
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                failures.Add($"binary file {i}: {ex.GetType().Name} {ex.Message}");
            }
        }

        failures.Should().BeEmpty();
    }

    [Fact]
    public void Parse_Truncations_AreProblemsNeverExceptions()
    {
        var failures = new List<string>();
        var lastBrace = SampleProject.Text.LastIndexOf('}');
        for (var length = 0; length <= lastBrace; length += length < lastBrace - 200 ? 3 : 1)
        {
            if (Parse(SampleProject.Text[..length], $"truncation to {length}", failures) is { Ok: true })
            {
                failures.Add($"truncation to {length} loaded");
            }
        }

        failures.Should().BeEmpty();
    }

    [Fact]
    public void Parse_EveryValueReplacedByEveryJsonKind_NeverThrowsAndReportsUnderThatPath()
    {
        var failures = new List<string>();
        var paths = Walk(SampleProject.Tree()).Select(n => n.GetPath()).ToList();
        for (var index = 1; index < paths.Count; index++)
        {
            foreach (var replacement in Replacements)
            {
                // Spliced in as text: JsonNode itself refuses to write some of the replacements (a lone surrogate).
                var tree = SampleProject.Tree();
                Walk(tree).ElementAt(index).ReplaceWith(JsonValue.Create(Placeholder));
                var text = tree.ToJsonString().Replace($"\"{Placeholder}\"", replacement, StringComparison.Ordinal);
                var because = $"{paths[index]} = {replacement}";

                var result = Parse(text, because, failures);

                // No property of the format holds an array of arrays, so the problem must sit at or under the path.
                if (replacement == "[[]]" && result is not null && !result.Errors.Any(e => e.Location.StartsWith(paths[index], StringComparison.Ordinal)))
                {
                    failures.Add($"{because}: no problem at or under the path");
                }
            }
        }

        failures.Should().BeEmpty();
    }

    private static ProjectLoadResult? Parse(string text, string because, List<string> failures)
    {
        try
        {
            var result = ProjectFile.Parse(text);
            if (result.Ok == result.Errors.Length > 0 || result.Errors.Any(e => e.Location.Length == 0 || e.Message.Length == 0))
            {
                failures.Add($"{because}: inconsistent result");
            }

            return result;
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            failures.Add($"{because}: {ex.GetType().Name} {ex.Message}");
            return null;
        }
    }

    /// <summary>Every node, depth first; of each array only the first two elements, which is where the shapes repeat.</summary>
    private static IEnumerable<JsonNode> Walk(JsonNode node) => node switch
    {
        JsonObject o => o.Select(p => p.Value!).SelectMany(Walk).Prepend(node),
        JsonArray a => a.Take(2).Select(e => e!).SelectMany(Walk).Prepend(node),
        _ => [node],
    };
}

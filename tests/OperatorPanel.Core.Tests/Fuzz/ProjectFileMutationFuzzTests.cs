using System.Text;
using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Tests.Projects;

namespace OperatorPanel.Core.Tests.Fuzz;

/// <summary>
/// Project files beyond the byte-level fuzz of <see cref="ProjectFileFuzzTests"/>: the starter project of every CPU and
/// the sample with entries duplicated, addresses moved out of the CPU's range, CPUs and alarm bits replaced, files
/// nested deep, grown to 10 MB, given byte order marks or another encoding. Loading returns problems with a location,
/// never throws; a valid file saves back unchanged.
/// </summary>
public sealed class ProjectFileMutationFuzzTests
{
    private static readonly string[] BadAddresses =
        ["VB99999", "VW10239", "I16.0", "Q0.8", "M32.0", "SMB550", "AIW63", "VD-1", "V.1", "", " ", "I 0.0", "16#GG", "VB" + new string('9', 300)];

    private static readonly string[] Lists = ["inputs", "outputs", "tags", "alarms"];

    public static TheoryData<string> Sources() =>
        ["sample", .. CpuProfiles.All.Select(cpu => $"starter {cpu.Model} {cpu.Revision}")];

    [Theory]
    [MemberData(nameof(Sources))]
    public void Format_ValidProject_SavesBackUnchanged(string source)
    {
        var text = Text(source);
        var loaded = ProjectFile.Parse(text);
        loaded.Ok.Should().BeTrue(string.Join("; ", loaded.Errors));

        ProjectFile.Format(loaded.Project!).Should().Be(text);
    }

    [Theory]
    [MemberData(nameof(Sources))]
    public void Parse_EntriesDuplicatedAndAddressesBroken_ReportsEachAtItsPath(string source)
    {
        var random = new Random(AddressSeed(source));
        var failures = new List<string>();
        for (var i = 0; i < 120; i++)
        {
            var tree = JsonNode.Parse(Text(source))!.AsObject();
            var (path, how) = Break(tree, random);
            if (path is null)
            {
                continue;
            }

            var because = $"{source} #{i}: {how}";
            try
            {
                var result = ProjectFile.Parse(tree.ToJsonString());
                if (result.Ok)
                {
                    failures.Add($"{because}: loaded");
                }
                else if (!result.Errors.Any(e => e.Location.StartsWith(path, StringComparison.Ordinal)))
                {
                    failures.Add($"{because}: no problem at {path}: {string.Join("; ", result.Errors)}");
                }
                else if (result.Errors.Any(e => e.Message.Length is 0 or > 400))
                {
                    failures.Add($"{because}: a message is empty or too long to read");
                }
            }
            catch (Exception ex) when (ex is not OutOfMemoryException)
            {
                failures.Add($"{because}: {ex.GetType().Name} {ex.Message}");
            }
        }

        failures.Should().BeEmpty();
    }

    [Theory]
    [MemberData(nameof(Sources))]
    public void Parse_TruncatedAtEveryLength_IsAProblemWithALineAndColumn(string source)
    {
        var text = Text(source);
        var step = Math.Max(1, text.Length / 1500);
        for (var length = 0; length < text.Length - 1; length += step)
        {
            var result = ProjectFile.Parse(text[..length]);

            result.Ok.Should().BeFalse($"truncated to {length}");
            result.Errors.Should().ContainSingle($"truncated to {length}").Which.Location.Should().MatchRegex("^line [0-9]+, column [0-9]+$");
        }
    }

    [Theory]
    [InlineData(100)]
    [InlineData(100_000)]
    public void Parse_DeepNesting_IsAProblemNotAStackOverflow(int depth)
    {
        var nested = new string('[', depth) + new string(']', depth);
        var inDescription = SampleProject.Text.Replace("\"Start push button (NO)\"", nested, StringComparison.Ordinal);

        foreach (var text in new[] { nested, inDescription })
        {
            var result = ProjectFile.Parse(text);

            result.Ok.Should().BeFalse();
            result.Errors.Should().NotBeEmpty().And.OnlyContain(e => e.Location.Length > 0 && e.Message.Length > 0 && e.Message.Length < 400);
        }
    }

    [Fact]
    public void Load_TenMegabyteFiles_GiveShortProblems()
    {
        using var folder = new TempFolder();
        var path = folder.File("huge.opproj");
        var longDescription = SampleProject.Text.Replace("Start push button (NO)", new string('x', 10 << 20), StringComparison.Ordinal);
        var longSymbol = SampleProject.Text.Replace("\"StartButton\"", "\"" + new string('S', 10 << 20) + "\"", StringComparison.Ordinal);
        var garbage = new string('{', 10 << 20);

        foreach (var (text, name) in new[] { (longDescription, "10 MB description"), (longSymbol, "10 MB symbol"), (garbage, "10 MB of '{'") })
        {
            File.WriteAllText(path, text);

            var result = ProjectFile.Load(path);

            result.Errors.Where(e => e.Message.Length >= 400 || e.Location.Length >= 400).Should().BeEmpty(name);
        }
    }

    [Fact]
    public void Load_ByteOrderMarksAndOtherEncodings_LoadOrNameTheEncoding()
    {
        using var folder = new TempFolder();
        var path = folder.File("encoded.opproj");
        var utf8 = Encoding.UTF8.GetBytes(SampleProject.Text);

        File.WriteAllBytes(path, [0xEF, 0xBB, 0xBF, .. utf8]);
        ProjectFile.Load(path).Ok.Should().BeTrue("a UTF-8 byte order mark is harmless");

        foreach (var encoding in new Encoding[] { Encoding.Unicode, Encoding.BigEndianUnicode, Encoding.UTF32, Encoding.Latin1 })
        {
            File.WriteAllBytes(path, [.. encoding.GetPreamble(), .. encoding.GetBytes(SampleProject.Text.Replace("Filler", "Füller", StringComparison.Ordinal))]);

            var result = ProjectFile.Load(path);

            result.Ok.Should().BeFalse(encoding.EncodingName);
            result.Errors.Should().ContainSingle().Which.Should().Match<ProjectFileError>(e => e.Location == "file" && e.Message.StartsWith("not UTF-8 text", StringComparison.Ordinal), encoding.EncodingName);
        }
    }

    private static string Text(string source)
    {
        if (source == "sample")
        {
            return SampleProject.Text;
        }

        var cpu = CpuProfiles.All.Single(c => source == $"starter {c.Model} {c.Revision}");
        return ProjectFile.Format(StarterProject.Create("Line", cpu, new Station(2), "COM1"));
    }

    private static int AddressSeed(string source) => source.Aggregate(5, (hash, c) => unchecked((hash * 31) + c));

    /// <summary>One edit that makes the project invalid, and the JSON path where the problem must be reported.</summary>
    private static (string? Path, string How) Break(JsonObject tree, Random random)
    {
        var stations = tree["stations"]!.AsArray();
        var stationIndex = random.Next(stations.Count);
        var station = stations[stationIndex]!.AsObject();
        var at = $"$.stations[{stationIndex}]";
        var lists = Lists.Where(l => station[l] is JsonArray { Count: > 0 }).ToArray();
        var list = lists.Length == 0 ? null : lists[random.Next(lists.Length)];
        var entries = list is null ? null : station[list]!.AsArray();
        var entryIndex = entries is null ? 0 : random.Next(entries.Count);
        switch (random.Next(7))
        {
            case 0 when entries is not null:
                entries.Add(entries[entryIndex]!.DeepClone());
                return ($"{at}.{list}[{entries.Count - 1}]", $"{list}[{entryIndex}] repeated");
            case 1:
                stations.Add(station.DeepClone());
                return ($"$.stations[{stations.Count - 1}]", $"station {stationIndex} repeated");
            case 2 when entries is not null:
                var property = list == "alarms" ? "flag" : "address";
                var bad = BadAddresses[random.Next(BadAddresses.Length)];
                entries[entryIndex]![property] = bad;
                return ($"{at}.{list}[{entryIndex}].{property}", $"{list}[{entryIndex}].{property} = '{bad}'");
            case 3:
                var model = new[] { "299", "", "CPU-224-", "S7-300", "2244", "226XM", "\u0000" }[random.Next(7)];
                station["cpu"]!["model"] = model;
                return ($"{at}.cpu.model", $"model '{model}'");
            case 4:
                var flag = new[] { "M32.0", "M31.8", "S0.0", "MB0", "AIW0", "T5" }[random.Next(6)];
                station["alarms"] = new JsonArray(new JsonObject { ["flag"] = flag, ["text"] = "Alarm" });
                return ($"{at}.alarms[0].flag", $"alarm flag {flag}");
            case 5:
                var name = new[] { "", " ", "\t" }[random.Next(3)];
                station["name"] = name;
                return ($"{at}.name", $"station name '{name}'");
            default:
                var number = new[] { 0, -1, 127, 255, int.MaxValue, int.MinValue }[random.Next(6)];
                station["address"] = number;
                return ($"{at}.address", $"station address {number}");
        }
    }
}

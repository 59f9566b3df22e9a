using System.Text.Json;

namespace OperatorPanel.Cli.Tests;

/// <summary>
/// A command line System.CommandLine cannot parse: one plain line per problem and a hint (never the help dump, never a
/// .NET type name), JSON on stdout with --json, exit 1 (bad input) either way.
/// </summary>
public sealed class CommandLineErrorTests
{
    public static TheoryData<string[], string[]> JsonCases() => new()
    {
        { ["address", "VB1", "--json"], ["opanel address needs --cpu (CPU model: 221, 222, 224, 224XP or 226)"] },
        { ["generate", "x.opproj", "--bogus", "--json"], ["opanel generate needs --output (Folder for the generated files)", "opanel generate has no option --bogus"] },
        { ["watch", "x.opproj", "--cycles", "x", "--json"], ["--cycles x: give a whole number"] },
        { ["read", "--demo", "--json"], ["opanel read needs at least one <address>"] },
    };

    [Theory]
    [MemberData(nameof(JsonCases))]
    public void ParseError_WithJson_PrintsOneJsonObjectOnStdoutAndExitsBadInput(string[] args, string[] errors)
    {
        var (exit, output, error) = CliRunner.Run(args);

        exit.Should().Be(1);
        error.Should().BeEmpty();
        output.Should().NotContain("Usage:");
        using var json = JsonDocument.Parse(output);
        var root = json.RootElement;
        root.GetProperty("ok").GetBoolean().Should().BeFalse();
        root.GetProperty("errors").EnumerateArray().Select(e => e.GetString()).Should().Equal(errors);
        root.GetProperty("error").GetString().Should().Be(errors.Length == 1 ? errors[0] : $"{errors.Length} problems on the command line");
        root.GetProperty("hint").GetString().Should().Be($"see opanel {args[0]} --help");
    }

    public static TheoryData<string[], string, string> TextCases() => new()
    {
        { ["watch", "p.opproj", "--duration", "abc"], "--duration abc: give a number of seconds", "watch" },
        { ["project", "new", "--cpu", "224", "-o", "x.opproj", "--station", "abc"], "--station abc: give a whole number", "project new" },
        { ["bench", "plan", "--tags", "abc"], "--tags abc: give whole numbers", "bench plan" },
        { ["watch", "p.opproj", "--model", "Foo"], "--model Foo: give stl or reference", "watch" },
        { ["simulate", "--cpu", "224", "--parity", "x"], "--parity x: give none, even or odd", "simulate" },
        { ["cpus", "--log-level", "loud"], "--log-level loud: give verbose, debug, information, warning, error or fatal", "cpus" },
        { ["address", "VB1"], "opanel address needs --cpu (CPU model: 221, 222, 224, 224XP or 226)", "address" },
        { ["cpus", "extra"], "opanel cpus takes no argument 'extra'", "cpus" },
        { ["bench"], "opanel bench needs a command: link, stl, plan or history", "bench" },
        { ["wach", "p.opproj", "--cycles", "3"], "opanel has no command 'wach': did you mean watch?", "" },
        { ["bench", "lnk"], "opanel bench has no command 'lnk': did you mean link?", "bench" },
        { ["project", "nwe", "--cpu", "224"], "opanel project has no command 'nwe': did you mean new?", "project" },
        { ["project", "frobnicate"], "opanel project has no command 'frobnicate'", "project" },
        { ["watch", "p.opproj", "--cyles", "3"], "opanel watch has no option --cyles (given '3'): did you mean --cycles?", "watch" },
        { ["cpus", "--jsno"], "opanel cpus has no option --jsno: did you mean --json?", "cpus" },
    };

    [Theory]
    [MemberData(nameof(TextCases))]
    public void ParseError_WithoutJson_SaysWhatTheOptionTakesOnStderrWithoutHelpOrTypeNames(string[] args, string message, string verb)
    {
        var (exit, output, error) = CliRunner.Run(args);

        exit.Should().Be(1);
        output.Should().BeEmpty();
        error.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal($"opanel: {message}", $"opanel: see {$"opanel {verb}".TrimEnd()} --help");
        error.Should().NotContain("System.").And.NotContain("OperatorPanel.").And.NotContain("Usage:");
    }

    [Fact]
    public void ParseError_ForTwoOptions_ReportsEachOnItsOwnLine()
    {
        var (exit, _, error) = CliRunner.Run("generate", "p.opproj", "--protocol", "x");

        exit.Should().Be(1);
        error.Split('\n', StringSplitOptions.RemoveEmptyEntries).Should().Equal(
            "opanel: opanel generate needs --output (Folder for the generated files)",
            "opanel: --protocol x: give a whole number",
            "opanel: see opanel generate --help");
    }

    [Fact]
    public void ValidEnumInAnyCase_StillParses()
    {
        var (exit, output, error) = CliRunner.Run("address", "VB1", "--cpu", "224", "--console-level", "warning");

        exit.Should().Be(0, error);
        output.Should().Contain("address   VB1");
    }

    [Fact]
    public void HelpWithABadOption_StillShowsTheHelp()
    {
        var (exit, output, _) = CliRunner.Run("watch", "--help", "--bogus");

        exit.Should().Be(0);
        output.Should().Contain("Usage:").And.Contain("--duration <seconds>");
    }
}

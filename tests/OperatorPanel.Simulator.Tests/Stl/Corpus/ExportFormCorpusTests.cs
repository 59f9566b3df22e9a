using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Run;
using OperatorPanel.Stl;
using OperatorPanel.Stl.Symbols;

namespace OperatorPanel.Simulator.Tests.Stl.Corpus;

/// <summary>
/// Programs in the forms real exports come in (docs/awl-exports.md): a password-protected POU exported without body
/// (ProtectedPou.awl), the code pages (Encodings/), symbolic operands with their symbol table (Symbols/), and what
/// Micro/WIN's import refuses (MicroWinRefuses/), which stl run warns about or refuses as the loader must.
/// </summary>
public sealed class ExportFormCorpusTests
{
    [Fact]
    public void ProtectedPou_WarnsNamingItAndRunsTheRest()
    {
        var load = StlProgramLoader.Load(CorpusProgram.Text("ProtectedPou.awl"), CorpusProgram.Cpu224);

        load.Succeeded.Should().BeTrue();
        load.Warnings.Should().ContainSingle().Which.ToString().Should().StartWith(
            "line 16: AWL015 PWM_INIT (SBR0) is password-protected: Micro/WIN exports it without its code");
        var run = CorpusProgram.Run("ProtectedPou.awl", 1, "I0.0=1");
        (run.Value("Q0.0"), run.Value("Q0.1")).Should().Be((1, 0));
    }

    [Theory]
    [InlineData("Cp1252.awl", AwlTextEncoding.Windows1252, "Zähler")]
    [InlineData("Gbk.awl", AwlTextEncoding.Gbk, "计数")]
    [InlineData("Utf8.awl", AwlTextEncoding.Utf8, "Zähler")]
    [InlineData("Utf8Bom.awl", AwlTextEncoding.Utf8WithByteOrderMark, "计数")]
    public void Encodings_DetectedNamesReadAndTheProgramRuns(string name, AwlTextEncoding encoding, string subroutine)
    {
        var source = AwlSource.Decode(File.ReadAllBytes(Path.Combine(CorpusProgram.Folder(), "Encodings", name)));

        source.Kind.Should().Be(encoding);
        AwlParser.Parse(source.Text).Program.Blocks[1].Name.Should().Be(subroutine);
        var load = StlProgramLoader.Load(source.Text, CorpusProgram.Cpu224);
        load.Succeeded.Should().BeTrue(string.Join("; ", load.Diagnostics));
        var run = new StlRun(load.Program!);
        run.Run(TimeSpan.FromSeconds(1), [.. CorpusProgram.Pulses("I0.0", 0.1, 0.3, 0.5).Select(Setting)]);
        (run.Value("VW0"), run.Value("Q0.0")).Should().Be((3, 1), "the subroutine, called by its name, counted three edges");
    }

    [Fact]
    public void Symbols_WithTheSymbolTable_RunsOnItsAddresses()
    {
        string[] settings = ["I0.0=1@0.1s", "I0.0=0@0.2s", .. CorpusProgram.Pulses("I0.2", 0.3, 0.4, 0.5, 0.6, 0.7, 0.8)];
        var run = RunConveyor(SymbolTable(), 1, settings);

        run.Value("Q0.0").Should().Be(1, "Conveyor_Motor latched by Start_PB");
        run.Value("VW100").Should().Be(6, "Bottle_Count");
        run.Value("VW102").Should().Be(6, "Crate_Size set on the first scan");
        run.Value("Q0.1").Should().Be(1, "Crate_Full");
    }

    [Fact]
    public void Symbols_SymbolMissingFromTheTable_RefusedNamingLineAndSymbol()
    {
        var table = AwlSymbolTable.Parse(File.ReadAllText(Path.Combine(CorpusProgram.Folder(), "Symbols", "Conveyor-symbols.txt")).Replace("Crate_Size", "Crate_Size_Old", StringComparison.Ordinal));
        var load = StlProgramLoader.Load(ConveyorText(), CorpusProgram.Cpu224, new StlLoadOptions { Symbols = table });

        load.Succeeded.Should().BeFalse();
        load.Diagnostics.Select(d => d.ToString()).Should().Equal(
            "line 15: LDW>=: symbol 'Crate_Size' is not in the symbol table", "line 20: MOVW: symbol 'Crate_Size' is not in the symbol table");
    }

    [Fact]
    public void Symbols_WithoutTheTable_RefusedAskingForIt()
    {
        var load = StlProgramLoader.Load(ConveyorText(), CorpusProgram.Cpu224);

        load.Diagnostics.First().Message.Should().Contain("'Start_PB' is not an address").And.Contain("--symbols");
    }

    [Theory]
    [InlineData("Ob1WithoutName.awl", true, "line 1: AWL012 Micro/WIN would refuse this file: the header of OB1 has no name")]
    [InlineData("CallMissing.awl", false, "line 6: CALL: 'VALVES' is not the name of a subroutine in this program")]
    [InlineData("SubroutineTwice.awl", false, "line 13: SBR_0 is defined twice")]
    public void MicroWinRefuses_StlRunWarnsOrRefuses(string name, bool runs, string finding)
    {
        var text = File.ReadAllText(Path.Combine(CorpusProgram.Folder(), "MicroWinRefuses", name));

        var load = StlProgramLoader.Load(text, CorpusProgram.Cpu224);

        load.Succeeded.Should().Be(runs);
        (runs ? load.Warnings : load.Diagnostics).Select(d => d.ToString()).Should().Contain(d => d.StartsWith(finding, StringComparison.Ordinal));
    }

    private static StlSetting Setting(string text) =>
        StlSetting.TryParse(text, CorpusProgram.Cpu224, out var setting, out var error) ? setting : throw new ArgumentException(error);

    private static string ConveyorText() => File.ReadAllText(Path.Combine(CorpusProgram.Folder(), "Symbols", "Conveyor.awl"));

    private static AwlSymbolTable SymbolTable() =>
        AwlSymbolTable.Parse(File.ReadAllText(Path.Combine(CorpusProgram.Folder(), "Symbols", "Conveyor-symbols.txt")));

    private static StlRun RunConveyor(AwlSymbolTable table, double seconds, params string[] settings)
    {
        var load = StlProgramLoader.Load(ConveyorText(), CorpusProgram.Cpu224, new StlLoadOptions { Symbols = table });
        load.Succeeded.Should().BeTrue(string.Join("; ", load.Diagnostics));
        var run = new StlRun(load.Program!);
        run.Run(TimeSpan.FromSeconds(seconds), [.. settings.Select(Setting)]);
        return run;
    }
}

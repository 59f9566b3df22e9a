using System.Text;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.StlGen;
using OperatorPanel.StlGen.Options;
using OperatorPanel.ViewModels.Generate;
using OperatorPanel.ViewModels.Tests.Fakes;

namespace OperatorPanel.ViewModels.Tests.Generate;

public sealed class GenerateCodeViewModelTests : IDisposable
{
    private readonly FakeFileDialogService _files = new();
    private readonly TempFolder _folder = new();

    public void Dispose() => _folder.Dispose();

    [Theory]
    [InlineData(CpuModel.Cpu222, "VB1442", "63", "125", new[] { 0 })]
    [InlineData(CpuModel.Cpu224, "VB7586", "63", "125", new[] { 0 })]
    [InlineData(CpuModel.Cpu226, "VB9634", "127", "125", new[] { 0, 1 })]
    public void Defaults_PerCpu_TheGeneratorsDefaultsShown(CpuModel model, string buffer, string sbr, string firstInt, int[] ports)
    {
        var cpu = CpuProfiles.For(model);
        var generate = Create(cpu);

        generate.BufferStart.Should().Be(buffer);
        generate.BufferStart.Should().Be($"VB{HandlerDefaults.V3First(cpu, compact: false)}", "V_FIRST of the protocol 3 handler the panel speaks");
        generate.FirstSubroutine.Should().Be(sbr);
        generate.FirstSubroutine.Should().Be(HandlerDefaults.FirstSubroutine(cpu).ToString(System.Globalization.CultureInfo.InvariantCulture));
        generate.FirstInterrupt.Should().Be(firstInt);
        generate.Ports.Should().Equal(ports);
        generate.Port.Should().Be(0);
        generate.CharTimeout.Should().Be("0");
        (generate.WriteQ, generate.WriteM, generate.WriteV).Should().Be((true, true, true));
        generate.LineText.Should().Be("9600 8N1");
        generate.CanSave.Should().BeFalse();
    }

    [Fact]
    public void Defaults_StationWithHandlerVFirst_BufferStartIsTheProjects()
    {
        var project = PanelFixture.Project(cpu: CpuProfiles.For(CpuModel.Cpu224));
        var generate = new GenerateCodeViewModel(project with { Stations = [project.Stations[0] with { HandlerVFirst = 1000 }] }, 0, _files);

        generate.BufferStart.Should().Be("VB1000", "the project records where the station's handler was generated");
    }

    [Fact]
    public void Generate_PortOneOnCpu224_ShowsTheStlDiagnosticAndSaveDisabled()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        generate.Port = 1;

        generate.GenerateCommand.Execute(null);

        generate.Diagnostics.Should().ContainSingle().Which.Id.Should().Be("STL001");
        generate.Diagnostics[0].Text.Should().StartWith("STL001: port 1 is not on the CPU 224");
        generate.SaveCommand.CanExecute(null).Should().BeFalse();
        generate.Preview.Should().BeEmpty();
        generate.Stats.Should().BeEmpty();
    }

    [Fact]
    public void Generate_BufferOutsideV_StlDiagnosticNamesTheRange()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        generate.BufferStart = "VB8000";

        generate.GenerateCommand.Execute(null);

        generate.Diagnostics.Select(d => d.Id).Should().Equal("STL005");
        generate.SaveCommand.CanExecute(null).Should().BeFalse();
    }

    [Fact]
    public void Generate_TextNotANumber_InputDiagnosticAndNoGeneration()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        generate.FirstSubroutine = "six";

        generate.GenerateCommand.Execute(null);

        generate.Diagnostics.Should().ContainSingle().Which.Text.Should().Be("INPUT: first SBR 'six' is not a whole number");
        generate.SaveCommand.CanExecute(null).Should().BeFalse();
    }

    [Fact]
    public void Save_AfterGenerate_WritesTheThreeFilesWithTheGeneratorsText()
    {
        var cpu = CpuProfiles.For(CpuModel.Cpu224);
        var generate = Create(cpu);
        generate.GenerateCommand.Execute(null);
        var expected = HandlerGenerator.Generate(new HandlerOptions { Protocol = 3, Cpu = cpu, Station = 2, WriteMask = 0x1C });
        _files.Folder = _folder.Path;

        generate.SaveCommand.CanExecute(null).Should().BeTrue();
        generate.SaveCommand.Execute(null);

        // The handler's upper size estimate is more than half a CPU 224's program memory: a warning, nothing refused.
        generate.Diagnostics.Should().ContainSingle().Which.Should().Match<GenerateDiagnosticRow>(d => d.Id == "STL050" && d.IsWarning);
        generate.Diagnostics[0].Message.Should().Be(expected.Stats!.Size.Warning);
        generate.Preview.Should().Be(expected.AwlText);
        generate.Stats.Should().Contain($"V memory: {expected.Stats!.VRange} ({expected.Stats.VBytes} bytes)")
            .And.Contain($"Program memory: 8192 bytes on the CPU 224 (with run mode edit; 12288 without)")
            .And.Contain($"Instructions: {expected.Stats.Instructions} in {expected.Stats.Size.Networks} networks");
        File.ReadAllText(_folder.File("Filler-handler.awl"), Encoding.ASCII).Should().Be(expected.AwlText);
        File.ReadAllText(_folder.File("Filler-symbols.txt"), Encoding.ASCII).Should().Be(expected.SymbolTableText);
        File.ReadAllText(_folder.File("Filler-README.txt"), Encoding.ASCII).Should().Be(expected.TechnicianText);
        Directory.GetFiles(_folder.Path).Should().HaveCount(3);
        generate.Message.Should().Be($"Saved Filler-handler.awl, Filler-symbols.txt, Filler-README.txt in {_folder.Path}.");
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Generate_StationAllowStop_TheHandlerCarriesStopAsTheProjectSays(bool allowStop)
    {
        var cpu = CpuProfiles.For(CpuModel.Cpu224);
        var project = PanelFixture.Project(cpu: cpu);
        var generate = new GenerateCodeViewModel(project with { Stations = [project.Stations[0] with { AllowStop = allowStop }] }, 0, _files);

        generate.GenerateCommand.Execute(null);

        generate.Preview.Should().Be(HandlerGenerator.Generate(new HandlerOptions { Protocol = 3, Cpu = cpu, Station = 2, AllowStop = allowStop }).AwlText);
        generate.Preview.Contains("08 STOP", StringComparison.Ordinal).Should().Be(allowStop);
        generate.StopText.Should().StartWith(allowStop ? "included" : "not included");
    }

    [Fact]
    public void Generate_CompactStationWithAllowStop_RefusedWithStl031AndTheStopLineSaysWhy()
    {
        var project = PanelFixture.Project(cpu: CpuProfiles.For(CpuModel.Cpu224));
        var generate = new GenerateCodeViewModel(project with { Stations = [project.Stations[0] with { Compact = true, AllowStop = true }] }, 0, _files);

        generate.GenerateCommand.Execute(null);

        generate.Diagnostics.Should().ContainSingle().Which.Id.Should().Be("STL031");
        generate.Preview.Should().BeEmpty();
        generate.SaveCommand.CanExecute(null).Should().BeFalse();
        generate.StopText.Should().StartWith("allowed, but the station's handler is compact, which has none");
    }

    [Fact]
    public void Save_SettingChangedAfterGenerate_DisabledUntilGeneratedAgain()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        generate.GenerateCommand.Execute(null);
        generate.SaveCommand.CanExecute(null).Should().BeTrue();

        generate.CharTimeout = "10";

        generate.SaveCommand.CanExecute(null).Should().BeFalse();
        generate.Preview.Should().BeEmpty();
    }

    [Fact]
    public void Generate_MergeProgramCollides_CollisionWithLineNumberAndNothingSaved()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        _files.FileToOpen = WriteProgram("MOVB   5, VB7920");
        generate.BrowseMergeCommand.Execute(null);
        _files.Folder = _folder.Path;

        generate.GenerateCommand.Execute(null);
        generate.SaveCommand.Execute(null);

        generate.MergeProgramPath.Should().Be(_files.FileToOpen);
        generate.Diagnostics.Should().Contain(d => d.Line == 6 && !d.IsWarning);
        generate.Diagnostics.Where(d => !d.IsWarning).Should().OnlyContain(d => d.Text.StartsWith("line ", StringComparison.Ordinal));
        generate.SaveCommand.CanExecute(null).Should().BeFalse();
        generate.Message.Should().StartWith("user.awl collides with the handler");
        Directory.GetFiles(_folder.Path).Should().ContainSingle().Which.Should().EndWith("user.awl");
    }

    [Fact]
    public void Save_MergeWithoutCollision_WritesTheMergedProgramBesideTheThreeFiles()
    {
        var generate = Create(CpuProfiles.For(CpuModel.Cpu224));
        generate.MergeProgramPath = WriteProgram("MOVB   5, VB100");
        var output = Directory.CreateDirectory(_folder.File("out")).FullName;
        _files.Folder = output;

        generate.GenerateCommand.Execute(null);
        generate.SaveCommand.Execute(null);

        generate.Diagnostics.Where(d => !d.IsWarning).Should().BeEmpty();
        Directory.GetFiles(output).Select(Path.GetFileName).Should().BeEquivalentTo(
            "Filler-handler.awl", "Filler-symbols.txt", "Filler-README.txt", "Filler-merged.awl");
        var merged = File.ReadAllText(Path.Combine(output, "Filler-merged.awl"), Encoding.Latin1);
        merged.Should().Be(generate.Preview);
        merged.Should().Contain("MOVB   5, VB100").And.Contain("CALL   OP_PANEL");
    }

    private string WriteProgram(string line)
    {
        var path = _folder.File("user.awl");
        File.WriteAllText(path, string.Join("\r\n",
            "ORGANIZATION_BLOCK MAIN:OB1", "TITLE=Main", "BEGIN", "Network 1", "LD     SM0.0", line, "END_ORGANIZATION_BLOCK", string.Empty));
        return path;
    }

    private GenerateCodeViewModel Create(CpuProfile cpu) => new(PanelFixture.Project(cpu: cpu), 0, _files);
}

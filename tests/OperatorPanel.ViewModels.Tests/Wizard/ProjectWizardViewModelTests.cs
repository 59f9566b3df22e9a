using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.ViewModels.Tests.Fakes;
using OperatorPanel.ViewModels.Wizard;

namespace OperatorPanel.ViewModels.Tests.Wizard;

public sealed class ProjectWizardViewModelTests
{
    public static TheoryData<CpuModel, CpuRevision> EveryCpu()
    {
        var data = new TheoryData<CpuModel, CpuRevision>();
        foreach (var profile in CpuProfiles.All)
        {
            data.Add(profile.Model, profile.Revision);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(EveryCpu))]
    public void Finish_EveryCpuModelAndRevision_BuildsAProjectThatPassesCheckAndRoundTrips(CpuModel model, CpuRevision revision)
    {
        var wizard = NewWizard();
        wizard.CpuStep.Cpu = CpuProfiles.For(model, revision);
        wizard.CpuStep.StationName = "Filler";
        wizard.CpuStep.StationAddress = "5";
        Next(wizard);
        wizard.IoStep.FillLocalPointsCommand.Execute(null);
        Next(wizard);
        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Speed", "VW100", DisplayFormat.Signed, writable: true, "Line speed"));
        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Batch", "MD4", DisplayFormat.Float));
        Next(wizard);
        wizard.AlarmStep.Alarms.Add(new AlarmTextRowViewModel("M0.0", "Conveyor jam"));
        wizard.AlarmStep.Alarms.Add(new AlarmTextRowViewModel("V100.3", "Glue low", AlarmClass.Warning, acknowledgementRequired: false));
        Next(wizard);
        wizard.LinkStep.BaudRate = wizard.LinkStep.BaudRates[^1];
        wizard.LinkStep.Kind = LinkKind.RadioModule;

        wizard.FinishCommand.CanExecute(null).Should().BeTrue(wizard.Message);
        wizard.FinishCommand.Execute(null);

        wizard.Message.Should().BeNull();
        var project = wizard.Result!;
        ProjectFile.Check(project).Should().BeEmpty();
        var reparsed = ProjectFile.Parse(ProjectFile.Format(project));
        reparsed.Ok.Should().BeTrue();
        ProjectFile.Format(reparsed.Project!).Should().Be(ProjectFile.Format(project));
        var station = project.Stations.Should().ContainSingle().Subject;
        station.Cpu.Should().Be(CpuProfiles.For(model, revision));
        station.Address.Address.Should().Be(5);
        station.Inputs.Should().HaveCount(station.Cpu.LocalDigitalInputs);
        station.Tags.Select(t => t.Symbol).Should().Equal("Speed", "Batch");
        station.Alarms.Select(a => a.Text).Should().Equal("Conveyor jam", "Glue low");
        station.Link.Should().Be(new SerialSettings { PortName = "COM3", BaudRate = wizard.LinkStep.BaudRates[^1], Kind = LinkKind.RadioModule });
    }

    [Fact]
    public void NewWizard_Defaults_CpuTwentyFourStationTwoFirstPortPresent()
    {
        var wizard = NewWizard();

        wizard.CpuStep.Cpu.Should().Be(CpuProfiles.For(CpuModel.Cpu224));
        wizard.CpuStep.StationAddress.Should().Be("2");
        wizard.IoStep.Inputs.Should().HaveCount(14);
        wizard.LinkStep.PortName.Should().Be("COM3");
        wizard.IsEditing.Should().BeFalse();
        wizard.FinishCommand.CanExecute(null).Should().BeFalse();
    }

    [Theory]
    [InlineData("200", "The station address 200 is outside 1-126.")]
    [InlineData("two", "Station address 'two' is not a number; use 1-126.")]
    public void Next_StationAddressInvalid_IsDisabledWithAMessage(string address, string message)
    {
        var wizard = NewWizard();

        wizard.CpuStep.StationAddress = address;

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be(message);
        wizard.CpuStep.StationAddress = "3";
        wizard.NextCommand.CanExecute(null).Should().BeTrue();
        wizard.Message.Should().BeNull();
    }

    [Fact]
    public void Back_FromSecondStep_ReturnsToTheFirst()
    {
        var wizard = NewWizard();
        Next(wizard);

        wizard.BackCommand.Execute(null);

        wizard.CurrentStep.Should().BeSameAs(wizard.CpuStep);
        wizard.BackCommand.CanExecute(null).Should().BeFalse();
    }

    [Fact]
    public void Edit_ExistingProject_IsPrefilledAndFinishReturnsTheEditedProject()
    {
        var original = AlarmProject.Create();
        var wizard = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());

        wizard.CpuStep.StationName.Should().Be("Filler");
        wizard.CpuStep.ProjectName.Should().Be("Bottling");
        wizard.AlarmStep.Alarms.Select(a => a.Flag).Should().Equal("M0.0", "V10.1", "M0.1");
        wizard.LinkStep.PortName.Should().Be("COM3");
        wizard.IoStep.Outputs.Should().HaveCount(10);

        wizard.AlarmStep.Alarms[1].Text = "Glue level low: refill";
        wizard.FinishCommand.Execute(null);

        var edited = wizard.Result!.Stations[0];
        edited.Alarms[1].Text.Should().Be("Glue level low: refill");
        ProjectFile.Format(wizard.Result with { Stations = [edited with { Alarms = original.Stations[0].Alarms }] })
            .Should().Be(ProjectFile.Format(original));
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Edit_StationAllowStop_IsPrefilledAndKeptOrChanged(bool allowStop)
    {
        var original = AlarmProject.Create();
        original = original with { Stations = [original.Stations[0] with { AllowStop = allowStop }] };
        var wizard = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());

        var prefilled = wizard.CpuStep.AllowStop;
        wizard.FinishCommand.Execute(null);
        var kept = wizard.Result!.Stations[0].AllowStop;
        var again = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());
        again.CpuStep.AllowStop = !allowStop;
        again.FinishCommand.Execute(null);

        prefilled.Should().Be(allowStop);
        kept.Should().Be(allowStop, "editing a project never drops its STOP setting");
        again.Result!.Stations[0].AllowStop.Should().Be(!allowStop);
    }

    [Theory]
    [InlineData(CpuModel.Cpu221, true)]
    [InlineData(CpuModel.Cpu222, true)]
    [InlineData(CpuModel.Cpu224, false)]
    [InlineData(CpuModel.Cpu226, false)]
    public void ChooseCpu_SmallCpu_CompactHandlerOfferedAndSaved(CpuModel model, bool compact)
    {
        var wizard = new ProjectWizardViewModel(AlarmProject.Create(), 0, new FakeConnectionTester(), new FakePortCatalog());

        wizard.CpuStep.Cpu = CpuProfiles.For(model);
        wizard.FinishCommand.Execute(null);

        wizard.LinkStep.Compact.Should().Be(compact, "the compact handler is the default offered for the CPUs with 4096 bytes of program");
        LinkStepViewModel.CompactHint.Should().Contain("CPU 221 or 222");
        wizard.Result!.Stations[0].Compact.Should().Be(compact);
    }

    [Fact]
    public void Edit_CompactStation_KeptUnlessTheCpuChanges()
    {
        var original = AlarmProject.Create();
        original = original with { Stations = [original.Stations[0] with { Compact = true }] };
        var wizard = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());

        wizard.FinishCommand.Execute(null);

        wizard.Result!.Stations[0].Compact.Should().BeTrue("editing a project never drops its handler shape");
    }

    [Fact]
    public void Edit_StationWithHandlerVFirst_KeptThroughTheWizard()
    {
        var original = AlarmProject.Create();
        original = original with { Stations = [original.Stations[0] with { HandlerVFirst = 1000 }] };
        var wizard = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());

        wizard.FinishCommand.Execute(null);

        wizard.Result!.Stations[0].HandlerVFirst.Should().Be(1000, "the wizard has no field for it, and editing never drops where the handler was generated");
    }

    [Fact]
    public void Finish_WritableCellInTheHandlersOwnVBytes_RefusedNamingTheCellAndTheRange()
    {
        var wizard = NewWizard();
        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("Speed", "VW8000") { Writable = true });
        var index = wizard.MemoryStep.Cells.Count - 1;
        wizard.CurrentIndex = 4;

        wizard.FinishCommand.Execute(null);

        wizard.IsFinished.Should().BeFalse();
        wizard.Message.Should().StartWith($"The project cannot be saved yet: $.stations[0].tags[{index}]: tag Speed (VW8000) is writable, "
            + "but VW8000 is in the handler's own V bytes VB7586-VB8191");
    }

    [Fact]
    public void ChooseCpu222WithAllowStop_LinkPageFlagsTheCompactHandlerWithoutStopAndFinishIsRefused()
    {
        var wizard = new ProjectWizardViewModel(AlarmProject.Create(), 0, new FakeConnectionTester(), new FakePortCatalog());
        wizard.CpuStep.AllowStop = true;
        wizard.CpuStep.Cpu = CpuProfiles.For(CpuModel.Cpu222);

        wizard.FinishCommand.Execute(null);

        wizard.IsFinished.Should().BeFalse("before, the station got a compact handler and the STOP allowed was silently left out");
        wizard.CurrentStep.Should().BeSameAs(wizard.LinkStep);
        wizard.Message.Should().Be("Step 5 (Link) needs attention: Filler (station 2) has \"Compact handler\" ticked and \"Allow remote STOP\" ticked on "
            + "step 1, but a compact handler has no STOP: it would be generated without the STOP that is allowed; clear \"Compact handler\" "
            + "for the full handler with STOP, or clear \"Allow remote STOP\" on step 1 for the compact handler without it.");
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Edit_CompactStationWithAllowStop_FinishesOnceEitherIsCleared(bool clearCompact)
    {
        var original = AlarmProject.Create();
        original = original with { Stations = [original.Stations[0] with { Compact = true, AllowStop = true }] };
        var wizard = new ProjectWizardViewModel(original, 0, new FakeConnectionTester(), new FakePortCatalog());
        wizard.CurrentIndex = 4;
        wizard.FinishCommand.CanExecute(null).Should().BeFalse(wizard.Message);

        if (clearCompact)
        {
            wizard.LinkStep.Compact = false;
        }
        else
        {
            wizard.CpuStep.AllowStop = false;
        }

        wizard.FinishCommand.Execute(null);

        var station = wizard.Result!.Stations[0];
        (station.Compact, station.AllowStop).Should().Be((!clearCompact, clearCompact));
    }

    [Theory]
    [InlineData("Fil\u001bler", "Step 1 (CPU and station) needs attention: The station name 'Fil<16#1B>ler' holds control characters (16#1B), which a screen does not show or takes as commands; remove them.")]
    [InlineData("FFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFF", "Step 1 (CPU and station) needs attention: The station name 'FFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFFF...' is 65 characters long; at most 64: generate names its files after it (NAME-handler.awl), and their path must fit in Windows' 260 characters.")]
    public void Finish_StationNameTheFileWouldRefuse_StepOneShowsTheFilesMessage(string name, string message)
    {
        var wizard = new ProjectWizardViewModel(AlarmProject.Create(), 0, new FakeConnectionTester(), new FakePortCatalog());
        wizard.CurrentIndex = 4;
        wizard.CpuStep.StationName = name;

        wizard.FinishCommand.Execute(null);

        wizard.IsFinished.Should().BeFalse();
        wizard.Message.Should().Be(message);
    }

    [Fact]
    public void AlarmText_WithAnEscape_RefusedWithTheFilesMessage()
    {
        var wizard = new ProjectWizardViewModel(AlarmProject.Create(), 0, new FakeConnectionTester(), new FakePortCatalog());
        wizard.CurrentIndex = 3;

        wizard.AlarmStep.Alarms[0].Text = "Jam\u001b[2J";

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be("Alarm 1 (M0.0): the alarm text 'Jam<16#1B>[2J' holds control characters (16#1B), which a screen does not show or takes as commands; remove them.");
    }

    [Fact]
    public void Finish_EarlierStepBrokenAfterLeavingIt_GoesBackThereWithAMessage()
    {
        var wizard = new ProjectWizardViewModel(AlarmProject.Create(), 0, new FakeConnectionTester(), new FakePortCatalog());
        wizard.CurrentIndex = 4;
        wizard.AlarmStep.Alarms[0].Text = " ";

        wizard.FinishCommand.Execute(null);

        wizard.IsFinished.Should().BeFalse();
        wizard.CurrentStep.Should().BeSameAs(wizard.AlarmStep);
        wizard.Message.Should().Be("Step 4 (Alarm texts) needs attention: Alarm 1 (M0.0): the alarm text is empty; the operator would see a blank message.");
    }

    [Fact]
    public void Finish_SymbolOfACellAlsoUsedByAnOutput_IsRefusedOnTheMemoryStep()
    {
        var wizard = NewWizard();
        wizard.MemoryStep.Cells.Add(new MemoryCellRowViewModel("output_0_0", "MB1"));
        wizard.CurrentIndex = 2;

        wizard.NextCommand.CanExecute(null).Should().BeFalse();
        wizard.Message.Should().Be("Cell 1 (MB1): symbol 'output_0_0' is already used.");
        wizard.MemoryStep.Cells[0].Error.Should().Be("symbol 'output_0_0' is already used");
    }

    [Fact]
    public void NewWizard_Cpu226Chosen_TheStarterIoListFollowsTheCpu()
    {
        var wizard = NewWizard();
        wizard.IoStep.Inputs[^1].Address.Should().Be("I1.5", "a new project starts with a CPU 224's points");

        wizard.CpuStep.Cpu = CpuProfiles.For(CpuModel.Cpu226);

        wizard.IoStep.Inputs.Should().HaveCount(24);
        wizard.IoStep.Inputs[^1].Address.Should().Be("I2.7");
        wizard.IoStep.Outputs.Should().HaveCount(16);
        wizard.IoStep.Outputs[^1].Address.Should().Be("Q1.7");
        wizard.IoStep.Outputs[^1].Symbol.Should().Be("Output_1_7");
    }

    [Fact]
    public void NewWizard_ListEditedThenCpuChanged_KeepsTheUsersList()
    {
        var wizard = NewWizard();
        wizard.IoStep.Inputs[0].Symbol = "StartButton";

        wizard.CpuStep.Cpu = CpuProfiles.For(CpuModel.Cpu226);

        wizard.IoStep.Inputs.Should().HaveCount(14, "the user's table is theirs; Fill the CPU's own points replaces it on request");
        wizard.IoStep.Inputs[0].Symbol.Should().Be("StartButton");
    }

    internal static ProjectWizardViewModel NewWizard() => new(new FakeConnectionTester(), new FakePortCatalog());

    private static void Next(ProjectWizardViewModel wizard)
    {
        wizard.NextCommand.CanExecute(null).Should().BeTrue(wizard.Message);
        wizard.NextCommand.Execute(null);
    }
}

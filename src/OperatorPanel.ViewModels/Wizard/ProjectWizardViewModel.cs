using CommunityToolkit.Mvvm.ComponentModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// The project wizard (seed 000 §7): five pages, Back/Next with each page checked before Next, and Finish building a
/// <see cref="PanelProject"/> that <see cref="ProjectFile.Check"/> accepts. Constructed from an existing project it edits
/// one station of it with every field prefilled ("the project can be freely edited later at any time"), and Finish may
/// be pressed on any page. The result is in <see cref="Result"/> once <see cref="IsFinished"/>.
/// </summary>
public sealed partial class ProjectWizardViewModel : ObservableObject
{
    private readonly PanelProject _original;
    private readonly int _stationIndex;
    private int _currentIndex;
    private string? _finishMessage;

    /// <summary>A new project: one CPU 224 at station 2 with its on-board I/O named, 9600 8N1 over a cable.</summary>
    /// <param name="tester">Step 5's test connection.</param>
    /// <param name="ports">The ports step 5 offers.</param>
    /// <param name="time">The clock that ends a test connection that hangs; the system clock by default.</param>
    public ProjectWizardViewModel(IConnectionTester tester, ISerialPortCatalog ports, TimeProvider? time = null)
        : this(NewProject(ports), 0, tester, ports, time, isEditing: false)
    {
    }

    /// <summary>Edits station <paramref name="stationIndex"/> of <paramref name="project"/>; the other stations are kept as they are.</summary>
    public ProjectWizardViewModel(PanelProject project, int stationIndex, IConnectionTester tester, ISerialPortCatalog ports, TimeProvider? time = null)
        : this(project, stationIndex, tester, ports, time, isEditing: true)
    {
    }

    private ProjectWizardViewModel(PanelProject project, int stationIndex, IConnectionTester tester, ISerialPortCatalog ports, TimeProvider? time, bool isEditing)
    {
        ArgumentNullException.ThrowIfNull(project);
        ArgumentNullException.ThrowIfNull(tester);
        ArgumentNullException.ThrowIfNull(ports);
        ArgumentOutOfRangeException.ThrowIfNegative(stationIndex);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(stationIndex, project.Stations.Length);
        (_original, _stationIndex, IsEditing) = (project, stationIndex, isEditing);
        var station = project.Stations[stationIndex];
        CpuStep = new CpuStepViewModel(project.Name, station.Cpu, station.Name, station.Address, station.AllowStop);
        IoStep = new IoSymbolsStepViewModel(station.Inputs, station.Outputs, () => CpuStep.Cpu);
        CpuStep.CpuChanged += IoStep.FollowCpu;
        MemoryStep = new MemoryCellsStepViewModel(station.Tags);
        AlarmStep = new AlarmTextsStepViewModel(station.Alarms);
        LinkStep = new LinkStepViewModel(station.Link, station.Compact, CpuStep, ports, tester, time ?? TimeProvider.System);
        Steps = [CpuStep, IoStep, MemoryStep, AlarmStep, LinkStep];
        foreach (var step in Steps)
        {
            step.Edited += OnEdited;
        }

        Revalidate();
    }

    public bool IsEditing { get; }

    public IReadOnlyList<WizardStepViewModel> Steps { get; }

    public CpuStepViewModel CpuStep { get; }

    public IoSymbolsStepViewModel IoStep { get; }

    public MemoryCellsStepViewModel MemoryStep { get; }

    public AlarmTextsStepViewModel AlarmStep { get; }

    public LinkStepViewModel LinkStep { get; }

    public int CurrentIndex
    {
        get => _currentIndex;
        set
        {
            if (SetProperty(ref _currentIndex, Math.Clamp(value, 0, Steps.Count - 1)))
            {
                OnPropertyChanged(nameof(CurrentStep));
                Revalidate();
            }
        }
    }

    public WizardStepViewModel CurrentStep => Steps[CurrentIndex];

    /// <summary>The wizard's window closed (Finish or Cancel): a test connection still running is stopped.</summary>
    public void Close()
    {
        if (LinkStep.TestConnectionCommand.IsRunning)
        {
            LinkStep.TestConnectionCancelCommand.Execute(null);
        }
    }

    /// <summary>Why Next or Finish is refused: the current page's first problem, or what Finish found; null when all is well.</summary>
    public string? Message => _finishMessage ?? CurrentStep.Message;

    [ObservableProperty]
    public partial PanelProject? Result { get; private set; }

    public bool IsFinished => Result is not null;

    private static PanelProject NewProject(ISerialPortCatalog ports)
    {
        ArgumentNullException.ThrowIfNull(ports);
        var present = ports.List();
        var port = present.Count > 0 ? present[0].PortName : OperatingSystem.IsWindows() ? "COM1" : "/dev/ttyUSB0";
        var project = StarterProject.Create("New line", CpuProfiles.For(CpuModel.Cpu224), new Station(2), port);
        return project with { Stations = [project.Stations[0] with { Name = "PLC 2" }] };
    }

    private void OnEdited()
    {
        _finishMessage = null;
        Result = null;
        OnPropertyChanged(nameof(IsFinished));
        Revalidate();
    }

    private void Revalidate()
    {
        CurrentStep.Validate(ContextFor(CurrentStep));
        OnPropertyChanged(nameof(Message));
        BackCommand.NotifyCanExecuteChanged();
        NextCommand.NotifyCanExecuteChanged();
        FinishCommand.NotifyCanExecuteChanged();
    }

    private WizardContext ContextFor(WizardStepViewModel step) =>
        new(CpuStep.Cpu, step == MemoryStep ? IoStep.Symbols() : new HashSet<string>(), LinkStep.Protocol);

    [RelayCommand(CanExecute = nameof(CanGoBack))]
    private void Back() => CurrentIndex--;

    [RelayCommand(CanExecute = nameof(CanGoNext))]
    private void Next() => CurrentIndex++;

    private bool CanGoBack() => CurrentIndex > 0;

    private bool CanGoNext() => CurrentIndex < Steps.Count - 1 && CurrentStep.IsValid;

    private bool CanFinish() => (IsEditing || CurrentIndex == Steps.Count - 1) && CurrentStep.IsValid;

    [RelayCommand(CanExecute = nameof(CanFinish))]
    private void Finish()
    {
        foreach (var step in Steps)
        {
            step.Validate(ContextFor(step));
            if (!step.IsValid)
            {
                CurrentIndex = step.Number - 1;
                _finishMessage = $"Step {step.Number} ({step.Title}) needs attention: {step.Message}";
                OnPropertyChanged(nameof(Message));
                return;
            }
        }

        var station = new ProjectStation(
            CpuStep.StationName.Trim(), CpuStep.Station!.Value, CpuStep.Cpu, LinkStep.Build(),
            IoStep.BuildInputs(), IoStep.BuildOutputs(), MemoryStep.Build(), AlarmStep.Build())
        {
            AllowStop = CpuStep.AllowStop,
            Compact = LinkStep.Compact && LinkStep.Protocol == LinkProtocol.Freeport,

            // The wizard has no field for it: an edited station keeps where its handler was generated (the file's check
            // below says so if the CPU or "compact" chosen no longer holds it there).
            HandlerVFirst = _original.Stations[_stationIndex].HandlerVFirst,
        };
        var project = _original with { Name = CpuStep.ProjectName.Trim(), Stations = _original.Stations.SetItem(_stationIndex, station) };
        var problems = ProjectFile.Check(project) is { IsEmpty: false } invalid ? invalid : ProjectChecks.Problems(project);
        if (!problems.IsEmpty)
        {
            _finishMessage = "The project cannot be saved yet: " + string.Join("; ", problems.Select(p => p.ToString()));
            OnPropertyChanged(nameof(Message));
            return;
        }

        Result = project;
        OnPropertyChanged(nameof(IsFinished));
    }
}

using System.Globalization;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>Step 1: the CPU model and revision (one list of every supported pair), the station's name and bus address.</summary>
public sealed class CpuStepViewModel : WizardStepViewModel
{
    private string _projectName;
    private CpuProfile _cpu;
    private string _stationName;
    private string _stationAddress;
    private bool _allowStop;

    internal CpuStepViewModel(string projectName, CpuProfile cpu, string stationName, Station station, bool allowStop = false)
    {
        _projectName = projectName;
        _cpu = cpu;
        _stationName = stationName;
        _stationAddress = station.Address.ToString(CultureInfo.InvariantCulture);
        _allowStop = allowStop;
    }

    /// <summary>The CPU changed; the argument is the one before (the I/O step follows it while it holds its starter list).</summary>
    internal event Action<CpuProfile>? CpuChanged;

    public override int Number => 1;

    public override string Title => "CPU and station";

    /// <summary>Every model and revision; <see cref="CpuProfile.DisplayName"/> is the text to show ("CPU 224 (early)").</summary>
    public IReadOnlyList<CpuProfile> Cpus { get; } = CpuProfiles.All;

    public string ProjectName { get => _projectName; set => Edit(ref _projectName, value ?? string.Empty); }

    public CpuProfile Cpu
    {
        get => _cpu;
        set
        {
            ArgumentNullException.ThrowIfNull(value);
            var previous = _cpu;
            Edit(ref _cpu, value);
            if (previous != value)
            {
                CpuChanged?.Invoke(previous);
            }
        }
    }

    public string StationName { get => _stationName; set => Edit(ref _stationName, value ?? string.Empty); }

    /// <summary>The RS-485 station address as typed, 1-126 (S7-200 ports default to 2).</summary>
    public string StationAddress { get => _stationAddress; set => Edit(ref _stationAddress, value ?? string.Empty); }

    /// <summary>
    /// The project's "allowStop": the generated handler carries STOP and the panel offers Stop PLC for this station.
    /// Off unless chosen: a remote STOP halts the line.
    /// </summary>
    public bool AllowStop { get => _allowStop; set => Edit(ref _allowStop, value); }

    /// <summary>The typed station address when valid.</summary>
    internal Station? Station =>
        int.TryParse(StationAddress.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out var n) && Core.Addressing.Station.TryCreate(n, out var s, out _)
            ? s
            : null;

    internal override IEnumerable<string> Check(WizardContext context)
    {
        if (WizardText.Check(TextRule.ProjectName, ProjectName) is { } projectName)
        {
            yield return WizardText.Sentence(projectName);
        }

        if (string.IsNullOrWhiteSpace(StationName))
        {
            yield return "The station needs a name, e.g. \"Filler\".";
        }
        else if (WizardText.Check(TextRule.StationName, StationName) is { } stationName)
        {
            yield return WizardText.Sentence(stationName);
        }

        if (!int.TryParse(StationAddress.Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, out var number))
        {
            yield return $"Station address '{StationAddress}' is not a number; use {Core.Addressing.Station.Min}-{Core.Addressing.Station.Max}.";
        }
        else if (!Core.Addressing.Station.TryCreate(number, out _, out var error))
        {
            yield return $"The {error}.";
        }
    }
}

using System.Collections.Immutable;
using System.Collections.ObjectModel;
using CommunityToolkit.Mvvm.Input;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Step 4: alarm texts on flag bits (seed 000 §7: "texts of messages, which will be displayed when activation of an
/// appropriate marker in the PLC memory is detected"). Flags are M or V bits the CPU has; one alarm per flag.
/// </summary>
public sealed partial class AlarmTextsStepViewModel : WizardStepViewModel
{
    internal AlarmTextsStepViewModel(IEnumerable<AlarmDefinition> alarms)
    {
        Alarms = new ObservableCollection<AlarmTextRowViewModel>(alarms.Select(a => new AlarmTextRowViewModel(a)));
        Track(Alarms);
    }

    public override int Number => 4;

    public override string Title => "Alarm texts";

    public ObservableCollection<AlarmTextRowViewModel> Alarms { get; }

    [RelayCommand]
    private void Add() => Alarms.Add(new AlarmTextRowViewModel());

    [RelayCommand]
    private void Remove(AlarmTextRowViewModel? row)
    {
        if (row is not null)
        {
            Alarms.Remove(row);
        }
    }

    internal ImmutableArray<AlarmDefinition> Build() =>
        [.. Alarms.Select(r => new AlarmDefinition(PlcAddress.Parse(r.Flag.Trim()), r.Text.Trim(), r.Class, r.AcknowledgementRequired))];

    internal override IEnumerable<string> Check(WizardContext context)
    {
        var flags = new HashSet<PlcAddress>();
        var problems = new List<string>();
        for (var i = 0; i < Alarms.Count; i++)
        {
            var row = Alarms[i];
            var error = WizardAddress.Check(row.Flag, context, AddressUse.Read, Shape, out var flag);
            error ??= flags.Add(flag) ? null : $"{flag} already has an alarm";
            error ??= string.IsNullOrWhiteSpace(row.Text) ? "the alarm text is empty; the operator would see a blank message" : null;
            error ??= WizardText.Check(TextRule.AlarmText, row.Text);
            row.Error = error;
            if (error is not null)
            {
                problems.Add($"Alarm {i + 1} ({(string.IsNullOrWhiteSpace(row.Flag) ? "no flag" : row.Flag.Trim())}): {error}.");
            }
        }

        return problems;
    }

    private static string? Shape(PlcAddress address) =>
        WizardAddress.IsBitOf(address, MemoryArea.M, MemoryArea.V) ? null : $"an alarm flag is an M or V bit such as M2.0 or V100.3, not {address}";
}

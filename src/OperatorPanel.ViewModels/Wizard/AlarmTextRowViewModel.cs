using OperatorPanel.Core.Alarms;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>An alarm being edited: its flag bit, text, class and whether the operator must acknowledge it.</summary>
public sealed class AlarmTextRowViewModel : WizardRowViewModel
{
    private string _flag;
    private string _text;
    private AlarmClass _class;
    private bool _acknowledgementRequired;

    public AlarmTextRowViewModel(string flag = "", string text = "", AlarmClass alarmClass = AlarmClass.Fault, bool acknowledgementRequired = true)
    {
        (_flag, _text, _class, _acknowledgementRequired) = (flag, text, alarmClass, acknowledgementRequired);
    }

    internal AlarmTextRowViewModel(AlarmDefinition alarm)
        : this(alarm.Flag.ToString(), alarm.Text, alarm.Class, alarm.AcknowledgementRequired)
    {
    }

    public static IReadOnlyList<AlarmClass> Classes { get; } = Enum.GetValues<AlarmClass>();

    public string Flag { get => _flag; set => Edit(ref _flag, value ?? string.Empty); }

    public string Text { get => _text; set => Edit(ref _text, value ?? string.Empty); }

    public AlarmClass Class { get => _class; set => Edit(ref _class, value); }

    public bool AcknowledgementRequired { get => _acknowledgementRequired; set => Edit(ref _acknowledgementRequired, value); }
}

using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Session;

/// <summary>The one line at the bottom of the shell: the latest thing the operator should know (a write, a failure).</summary>
public sealed partial class StatusLine : ObservableObject
{
    [ObservableProperty]
    public partial string Text { get; private set; } = "Ready";

    [ObservableProperty]
    public partial bool IsError { get; private set; }

    public void Show(string text) => (Text, IsError) = (text, false);

    public void ShowError(string text) => (Text, IsError) = (text, true);
}

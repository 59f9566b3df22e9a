using OperatorPanel.ViewModels.Mvvm;

namespace OperatorPanel.ViewModels.Session;

/// <summary>The one line at the bottom of the shell: the latest thing the operator should know (a write, a failure).</summary>
public sealed class StatusLine : ObservableObject
{
    private string _text = "Ready";
    private bool _isError;

    public string Text
    {
        get => _text;
        private set => SetProperty(ref _text, value);
    }

    public bool IsError
    {
        get => _isError;
        private set => SetProperty(ref _isError, value);
    }

    public void Show(string text) => (Text, IsError) = (text, false);

    public void ShowError(string text) => (Text, IsError) = (text, true);
}

namespace OperatorPanel.ViewModels.Services;

/// <summary>The three answers to "save changes?": save first, discard, or keep the project open.</summary>
public enum SaveChangesAnswer
{
    Save,
    Discard,
    Cancel,
}

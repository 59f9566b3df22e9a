namespace OperatorPanel.ViewModels.Session;

public enum ProjectChangeKind
{
    /// <summary>Another project: new, opened, or the demo. Windows rebuild their rows.</summary>
    Replaced,

    /// <summary>The same project edited (a memory cell added, moved, reformatted): it is now unsaved.</summary>
    Edited,

    /// <summary>The project was saved; nothing in it changed.</summary>
    Saved,
}

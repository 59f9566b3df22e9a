namespace OperatorPanel.Core.Messages;

/// <summary>What was being done to a file when it failed, for <see cref="FileProblemText"/>.</summary>
public enum FileAction
{
    Read,
    Write,
}

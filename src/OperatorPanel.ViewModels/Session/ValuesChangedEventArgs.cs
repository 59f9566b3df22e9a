using OperatorPanel.Core.Polling;

namespace OperatorPanel.ViewModels.Session;

/// <summary>A batch of changed values, raised on the UI thread. An empty batch after a reset means "read everything again".</summary>
public sealed class ValuesChangedEventArgs(IReadOnlyList<ValueChange> changes, bool reset) : EventArgs
{
    public IReadOnlyList<ValueChange> Changes { get; } = changes;

    /// <summary>The engines were replaced (connect, disconnect, a new watch list): every row re-reads its value.</summary>
    public bool Reset { get; } = reset;
}

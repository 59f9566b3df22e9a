using OperatorPanel.Core.Polling;
using OperatorPanel.ViewModels.Values;

namespace OperatorPanel.ViewModels.Session;

/// <summary>
/// The session as an <see cref="IValueChangeSource"/>: the Alarms window hears the same batches as the other windows,
/// from whichever engine runs now, through <see cref="ValuesChanged"/> (already on the UI thread). Reset batches carry
/// no changes and are not passed on.
/// </summary>
public sealed partial class PanelSession : IValueChangeSource
{
    public IDisposable Subscribe(Action<IReadOnlyList<ValueChange>> onChanges)
    {
        ArgumentNullException.ThrowIfNull(onChanges);
        void Handler(object? sender, ValuesChangedEventArgs e)
        {
            if (e.Changes.Count > 0)
            {
                onChanges(e.Changes);
            }
        }

        ValuesChanged += Handler;
        return new Unsubscriber(() => ValuesChanged -= Handler);
    }

    private sealed class Unsubscriber(Action unsubscribe) : IDisposable
    {
        private Action? _unsubscribe = unsubscribe;

        public void Dispose() => Interlocked.Exchange(ref _unsubscribe, null)?.Invoke();
    }
}

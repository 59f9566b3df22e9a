using System.Collections.Immutable;
using OperatorPanel.Core.Polling;

namespace OperatorPanel.ViewModels.Values;

/// <summary>
/// Passes value changes from the current engine to every subscriber: the shell calls
/// <c>engine.Subscribe(relay.Publish)</c> per connection, the view models subscribe to the relay once. Thread-safe.
/// </summary>
public sealed class ValueChangeRelay : IValueChangeSource
{
    private readonly Lock _gate = new();
    private ImmutableArray<Action<IReadOnlyList<ValueChange>>> _subscribers = [];

    public IDisposable Subscribe(Action<IReadOnlyList<ValueChange>> onChanges)
    {
        ArgumentNullException.ThrowIfNull(onChanges);
        lock (_gate) { _subscribers = _subscribers.Add(onChanges); }
        return new Unsubscriber(() => { lock (_gate) { _subscribers = _subscribers.Remove(onChanges); } });
    }

    public void Publish(IReadOnlyList<ValueChange> changes)
    {
        ArgumentNullException.ThrowIfNull(changes);
        ImmutableArray<Action<IReadOnlyList<ValueChange>>> subscribers;
        lock (_gate) { subscribers = _subscribers; }
        foreach (var subscriber in subscribers)
        {
            subscriber(changes);
        }
    }

    private sealed class Unsubscriber(Action unsubscribe) : IDisposable
    {
        private Action? _unsubscribe = unsubscribe;

        public void Dispose() => Interlocked.Exchange(ref _unsubscribe, null)?.Invoke();
    }
}

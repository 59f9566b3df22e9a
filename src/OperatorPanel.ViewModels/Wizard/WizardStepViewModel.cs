using System.Collections.Immutable;
using System.Collections.ObjectModel;
using System.Collections.Specialized;
using CommunityToolkit.Mvvm.ComponentModel;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>One page of the project wizard (seed 000 §7: five steps). The wizard checks it after every edit.</summary>
public abstract class WizardStepViewModel : ObservableObject
{
    private ImmutableArray<string> _problems = [];

    internal event Action? Edited;

    public abstract int Number { get; }

    public abstract string Title { get; }

    /// <summary>Everything wrong on this page, each naming the row and value; empty when the page is valid.</summary>
    public ImmutableArray<string> Problems
    {
        get => _problems;
        private set
        {
            if (!_problems.SequenceEqual(value))
            {
                _problems = value;
                OnPropertyChanged();
                OnPropertyChanged(nameof(IsValid));
                OnPropertyChanged(nameof(Message));
            }
        }
    }

    public bool IsValid => Problems.IsEmpty;

    /// <summary>The first problem, for the line under the page; null when valid.</summary>
    public string? Message => Problems.IsEmpty ? null : Problems[0];

    internal void Validate(WizardContext context) => Problems = [.. Check(context)];

    internal abstract IEnumerable<string> Check(WizardContext context);

    protected void Edit<T>(ref T field, T value, [System.Runtime.CompilerServices.CallerMemberName] string? propertyName = null)
    {
        if (SetProperty(ref field, value, propertyName))
        {
            RaiseEdited();
        }
    }

    protected void RaiseEdited() => Edited?.Invoke();

    /// <summary>Reports edits of the rows of <paramref name="rows"/>, and rows added or removed.</summary>
    protected void Track<T>(ObservableCollection<T> rows)
        where T : WizardRowViewModel
    {
        ArgumentNullException.ThrowIfNull(rows);
        foreach (var row in rows)
        {
            row.Edited += RaiseEdited;
        }

        rows.CollectionChanged += (_, e) =>
        {
            foreach (var row in e.NewItems?.OfType<T>() ?? [])
            {
                row.Edited += RaiseEdited;
            }

            foreach (var row in e.OldItems?.OfType<T>() ?? [])
            {
                row.Edited -= RaiseEdited;
            }

            if (e.Action != NotifyCollectionChangedAction.Move || e.OldStartingIndex != e.NewStartingIndex)
            {
                RaiseEdited();
            }
        };
    }
}

using System.Windows.Threading;
using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.App.Services;

/// <summary>Posts the line's batches (values, then StateChanged) to the UI thread.</summary>
public sealed class WpfDispatcher(Dispatcher dispatcher) : IUiDispatcher
{
    public void Post(Action action) => dispatcher.BeginInvoke(action);
}

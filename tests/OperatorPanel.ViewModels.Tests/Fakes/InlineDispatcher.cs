using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Runs posted work at once, on the caller's thread.</summary>
internal sealed class InlineDispatcher : IUiDispatcher
{
    public void Post(Action action) => action();
}

using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Runs posted work at once, on the posting thread (the engine's); tests assert after awaiting the engine.</summary>
internal sealed class InlineDispatcher : IUiDispatcher
{
    public void Post(Action action) => action();
}

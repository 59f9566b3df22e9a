using OperatorPanel.ViewModels.Services;

namespace OperatorPanel.ViewModels.Tests.Fakes;

/// <summary>Answers questions from a script and records every question and error shown.</summary>
internal sealed class ScriptedDialogService : IDialogService
{
    public Queue<bool> ConfirmAnswers { get; } = new();

    public Queue<SaveChangesAnswer> SaveAnswers { get; } = new();

    public List<string> Questions { get; } = [];

    public List<(string Title, string Message)> Errors { get; } = [];

    /// <summary>For every question asked, whether Enter would have answered No.</summary>
    public List<bool> NoByDefault { get; } = [];

    public Task<bool> ConfirmAsync(string title, string message, bool noByDefault = false)
    {
        Questions.Add(message);
        NoByDefault.Add(noByDefault);
        return Task.FromResult(ConfirmAnswers.Dequeue());
    }

    public Task<SaveChangesAnswer> AskSaveChangesAsync(string projectName)
    {
        Questions.Add($"Save changes to {projectName}?");
        return Task.FromResult(SaveAnswers.Dequeue());
    }

    public Task ShowErrorAsync(string title, string message)
    {
        Errors.Add((title, message));
        return Task.CompletedTask;
    }
}

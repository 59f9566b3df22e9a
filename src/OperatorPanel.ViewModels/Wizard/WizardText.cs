using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// The names and texts typed into the wizard, checked by Core's <see cref="TextRule"/>, the rule the project file is
/// read by: the page shows the message the file would get.
/// </summary>
internal static class WizardText
{
    /// <summary>The rule's message for <paramref name="text"/> as typed (spaces around it are trimmed when saved); null when it keeps it.</summary>
    public static string? Check(TextRule rule, string text) => rule.Problem(text.Trim());

    /// <summary>A message as a page's own line says it: a capital first and a full stop.</summary>
    public static string Sentence(string message) => string.Concat(message[..1].ToUpperInvariant(), message.AsSpan(1), ".");
}

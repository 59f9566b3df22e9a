using System.Globalization;

namespace OperatorPanel.ViewModels.Generate;

/// <summary>
/// One reason the handler cannot be generated or merged: a stable ID (STL001..., or "INPUT" for text that is not a
/// number), the 1-based line of the user's program for a merge collision (0 when none), and what to do.
/// </summary>
public sealed record GenerateDiagnosticRow(string Id, int Line, string Message, bool IsWarning = false)
{
    /// <summary>"STL003: port 1 is not on the CPU 224 ...", or "line 57: STL022 ...".</summary>
    public string Text => Line > 0
        ? string.Create(CultureInfo.InvariantCulture, $"line {Line}: {Id} {Message}")
        : $"{Id}: {Message}";
}

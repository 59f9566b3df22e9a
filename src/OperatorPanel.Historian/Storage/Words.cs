using System.Text.Json;

namespace OperatorPanel.Historian.Storage;

/// <summary>Enum values as the database stores them: the project file's camelCase words ("raised", "activeUnacknowledged").</summary>
internal static class Words
{
    public static string Of<T>(T value)
        where T : struct, Enum => JsonNamingPolicy.CamelCase.ConvertName(value.ToString());

    public static T Parse<T>(string text)
        where T : struct, Enum =>
        TryParse<T>(text, out var value) ? value : throw new HistoryException(HistoryErrorKind.Corrupt, $"unknown {typeof(T).Name} '{text}' in the history database");

    public static bool TryParse<T>(string text, out T value)
        where T : struct, Enum
    {
        foreach (var candidate in Enum.GetValues<T>())
        {
            if (string.Equals(Of(candidate), text, StringComparison.OrdinalIgnoreCase))
            {
                value = candidate;
                return true;
            }
        }

        value = default;
        return false;
    }
}

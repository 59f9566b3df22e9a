using System.Globalization;

namespace OperatorPanel.Core.Projects;

/// <summary>Builds the JSONPath locations of problems: <c>$.stations[0].tags[3].address</c>.</summary>
internal static class JsonPath
{
    public const string Root = "$";

    public static string Property(string parent, string name) => IsPlainName(name)
        ? $"{parent}.{name}"
        : $"{parent}['{Shorten(name).Replace("\\", "\\\\", StringComparison.Ordinal).Replace("'", "\\'", StringComparison.Ordinal)}']";

    public static string Index(string parent, int index) => string.Create(CultureInfo.InvariantCulture, $"{parent}[{index}]");

    /// <summary>Cuts user text quoted in a message, so a megabyte of garbage does not become a megabyte of report.</summary>
    public static string Shorten(string text)
    {
        const int Max = 40;
        var printable = string.Concat(text.Take(Max + 1).Select(c => char.IsControl(c) ? '?' : c));
        return printable.Length > Max ? printable[..Max] + "..." : printable;
    }

    private static bool IsPlainName(string name) =>
        name.Length is > 0 and <= 40 && name.All(char.IsAsciiLetterOrDigit) && char.IsAsciiLetter(name[0]);
}

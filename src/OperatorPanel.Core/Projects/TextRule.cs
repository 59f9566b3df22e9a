using System.Globalization;
using OperatorPanel.Core.Messages;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// What a name or text of a project may hold: the one rule behind the file (its readers), the wizard and the Memory
/// window. No control characters, U+0000-U+001F and U+007F-U+009F (<see cref="char.IsControl(char)"/>): a screen shows
/// them as nothing, and a terminal takes them as commands (ESC [ 2 J clears it, NUL ends a C string early). And at most
/// <see cref="MaxChars"/> characters as .NET counts them (a character beyond U+FFFF counts 2), each limit with its
/// reason. A project that breaks the rule does not load, in the panel as in every verb of <c>opanel</c>.
/// </summary>
/// <param name="Noun">How the message names the text: "the station name".</param>
/// <param name="MaxChars">The most characters the text may have.</param>
/// <param name="Why">Why the limit is what it is, said after it in the message.</param>
public sealed record TextRule(string Noun, int MaxChars, string Why)
{
    /// <summary>Names (project, station, symbol) are words an operator reads, not sentences.</summary>
    public const int MaxNameChars = 64;

    public static TextRule ProjectName { get; } = new("the project name", MaxNameChars,
        "it heads the panel's window and Save As offers it as the file name");

    /// <summary>
    /// 64 keeps "NAME-merged.awl" at 75 characters and the hidden temporary file each save writes beside it (a dot, the
    /// name, a dot, 32 hex digits and ".tmp") at 113, under the 255 a file name may have, leaving 145 of Windows' 260 for
    /// the folder. generate's file names keep letters, digits, '-' and '_' of the name and make the rest '_'.
    /// </summary>
    public static TextRule StationName { get; } = new("the station name", MaxNameChars,
        "generate names its files after it (NAME-handler.awl), and their path must fit in Windows' 260 characters");

    /// <summary>
    /// The project's own limit: generate never writes these symbols into a Micro/WIN file (its symbol table holds the
    /// handler's own V bytes only), so Micro/WIN's rules for its names do not apply here.
    /// </summary>
    public static TextRule Symbol { get; } = new("the symbol", MaxNameChars,
        "it is a name in a column of the Inputs, Outputs and Memory windows and an argument of opanel read and write");

    public static TextRule Description { get; } = new("the description", 256, "it is a comment for a tooltip or a column, not a document");

    public static TextRule AlarmText { get; } = new("the alarm text", 128, "the alarm banner shows it on one line in large type");

    public static TextRule Port { get; } = new("the serial port name", 128,
        "it names a device such as COM3 or /dev/serial/by-id/usb-FTDI_FT232R_USB_UART_A50285BI-if00-port0 (62 characters)");

    /// <summary>The message for <paramref name="text"/>, naming it and what is wrong; null when it keeps the rule.</summary>
    public string? Problem(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var controls = text.Where(char.IsControl).Distinct().ToList();
        if (controls.Count > 0)
        {
            var codes = string.Join(", ", controls.Take(4).Select(c => string.Create(CultureInfo.InvariantCulture, $"16#{(int)c:X2}")));
            return $"{Noun} '{Quote(text)}' holds control characters ({codes}{(controls.Count > 4 ? ", ..." : string.Empty)}), "
                + "which a screen does not show or takes as commands; remove them";
        }

        return text.Length > MaxChars
            ? string.Create(CultureInfo.InvariantCulture, $"{Noun} '{Quote(text)}' is {text.Length} characters long; at most {MaxChars}: {Why}")
            : null;
    }

    /// <summary>The string property <paramref name="name"/> of <paramref name="fields"/>, reported and null when it breaks the rule.</summary>
    internal string? Read(JsonFields fields, string name, string? fallback = null)
    {
        var text = fields.String(name, fallback);
        if (text is not null && Problem(text) is { } problem)
        {
            fields.Problem(name, problem);
            return null;
        }

        return text;
    }

    /// <summary>The text as a message quotes it: its first 40 characters, control characters shown as their codes.</summary>
    private static string Quote(string text)
    {
        const int Shown = 40;
        return text.Length > Shown ? QuotedText.OneLine(text[..Shown]) + "..." : QuotedText.OneLine(text);
    }
}

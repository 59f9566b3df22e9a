using System.Diagnostics.CodeAnalysis;
using System.Globalization;
using System.Text.Encodings.Web;
using System.Text.Json;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// One history entry as one line of JSON (JSON Lines): a line is complete or recognisably torn, and a reader can skip
/// to the next '\n'. Words are the project file's camelCase words.
/// </summary>
internal static class AlarmHistoryLine
{
    private static readonly JsonWriterOptions Options = new() { Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    public static string Format(AlarmEvent entry)
    {
        using var buffer = new MemoryStream();
        using (var json = new Utf8JsonWriter(buffer, Options))
        {
            json.WriteStartObject();
            json.WriteString("time", AlarmTime.Format(entry.At));
            json.WriteString("station", entry.StationName);
            json.WriteNumber("address", entry.Station.Address);
            json.WriteString("flag", entry.Flag.ToString());
            json.WriteString("event", JsonWords.Of(entry.Transition));
            json.WriteString("state", JsonWords.Of(entry.State));
            json.WriteString("class", JsonWords.Of(entry.Class));
            json.WriteString("text", entry.Text);
            json.WriteEndObject();
        }

        return System.Text.Encoding.UTF8.GetString(buffer.ToArray());
    }

    public static bool TryParse(string line, [NotNullWhen(true)] out AlarmEvent? entry, [NotNullWhen(false)] out string? error)
    {
        entry = null;
        try
        {
            using var document = JsonDocument.Parse(line);
            var root = document.RootElement;
            error = Read(root, out entry);
            return error is null;
        }
        catch (JsonException ex)
        {
            error = "not a JSON object: " + ex.Message;
            return false;
        }
        catch (InvalidOperationException ex)
        {
            error = "a field has the wrong type: " + ex.Message;
            return false;
        }
    }

    private static string? Read(JsonElement root, out AlarmEvent? entry)
    {
        entry = null;
        if (root.ValueKind != JsonValueKind.Object)
        {
            return "not a JSON object";
        }

        if (!AlarmTime.TryParse(Text(root, "time"), out var at))
        {
            return "time is missing or not an ISO 8601 UTC time";
        }

        if (!root.TryGetProperty("address", out var number) || !number.TryGetInt32(out var n) || !Station.TryCreate(n, out var station, out _))
        {
            return "address is missing or not a station address 1-126";
        }

        if (!PlcAddress.TryParse(Text(root, "flag"), out var flag, out _) || flag.Width != AccessWidth.Bit)
        {
            return "flag is missing or not a bit address";
        }

        if (!JsonWords.TryParse<AlarmTransition>(Text(root, "event") ?? string.Empty, out var transition)
            || !JsonWords.TryParse<AlarmState>(Text(root, "state") ?? string.Empty, out var state)
            || !JsonWords.TryParse<AlarmClass>(Text(root, "class") ?? string.Empty, out var alarmClass))
        {
            return "event, state or class is missing or unknown";
        }

        if (Text(root, "station") is not { } name || Text(root, "text") is not { } text)
        {
            return "station or text is missing";
        }

        entry = new AlarmEvent(at, name, station, flag, transition, state, alarmClass, text);
        return null;
    }

    private static string? Text(JsonElement root, string name) =>
        root.TryGetProperty(name, out var value) && value.ValueKind == JsonValueKind.String ? value.GetString() : null;

    public static string Describe(int lineNumber, string error) =>
        string.Create(CultureInfo.InvariantCulture, $"line {lineNumber}: {error}");
}

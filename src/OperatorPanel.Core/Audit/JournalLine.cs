using System.Diagnostics.CodeAnalysis;
using System.Text.Encodings.Web;
using System.Text.Json;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Alarms;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Audit;

/// <summary>
/// One journal entry as one line of JSON (JSON Lines, as the alarm history): the <see cref="AuditEntry"/> plus the
/// writing process (<paramref name="Pid"/> and its start time), so a later start tells an intent cut short (its process
/// is gone) from one still on the wire in another program.
/// </summary>
internal sealed record JournalLine(AuditEntry Entry, int Pid, DateTimeOffset ProcessStarted)
{
    private static readonly JsonWriterOptions Options = new() { Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    public string Format()
    {
        var e = Entry;
        using var buffer = new MemoryStream();
        using (var json = new Utf8JsonWriter(buffer, Options))
        {
            json.WriteStartObject();
            json.WriteString("id", e.Id);
            json.WriteString("step", JsonWords.Of(e.Step));
            json.WriteString("action", JsonWords.Of(e.Action));
            json.WriteString("time", AlarmTime.Format(e.At));
            json.WriteString("user", e.User);
            json.WriteString("port", e.Port);
            json.WriteNumber("station", e.Station.Address);
            json.WriteString("target", e.Target);
            json.WriteString("symbol", e.Symbol);
            json.WriteString("old", e.OldValue);
            json.WriteString("new", e.NewValue);
            json.WriteString("outcome", e.Outcome);
            json.WriteString("detail", e.Detail);
            json.WriteNumber("pid", Pid);
            json.WriteString("processStarted", AlarmTime.Format(ProcessStarted));
            json.WriteEndObject();
        }

        return System.Text.Encoding.UTF8.GetString(buffer.ToArray());
    }

    /// <summary>False for a line that is not an entry (torn by a kill while it was written, or edited by hand).</summary>
    public static bool TryParse(string text, [NotNullWhen(true)] out JournalLine? line)
    {
        line = null;
        try
        {
            using var document = JsonDocument.Parse(text);
            var root = document.RootElement;
            if (root.ValueKind != JsonValueKind.Object
                || !root.TryGetProperty("id", out var id) || !id.TryGetGuid(out var guid)
                || !JsonWords.TryParse<AuditStep>(Text(root, "step") ?? string.Empty, out var step)
                || !JsonWords.TryParse<AuditAction>(Text(root, "action") ?? string.Empty, out var action)
                || !AlarmTime.TryParse(Text(root, "time"), out var at)
                || !root.TryGetProperty("station", out var number) || !number.TryGetInt32(out var n) || !Station.TryCreate(n, out var station, out _)
                || !root.TryGetProperty("pid", out var pidValue) || !pidValue.TryGetInt32(out var pid)
                || !AlarmTime.TryParse(Text(root, "processStarted"), out var started)
                || Text(root, "user") is not { } user || Text(root, "port") is not { } port
                || Text(root, "old") is not { } old || Text(root, "new") is not { } requested)
            {
                return false;
            }

            var entry = new AuditEntry(guid, step, action, at, user, port, station, Text(root, "target"), Text(root, "symbol"), old, requested, Text(root, "outcome"), Text(root, "detail"));
            line = new JournalLine(entry, pid, started);
            return true;
        }
        catch (Exception ex) when (ex is JsonException or InvalidOperationException or FormatException)
        {
            return false;
        }
    }

    private static string? Text(JsonElement root, string name) =>
        root.TryGetProperty(name, out var value) && value.ValueKind == JsonValueKind.String ? value.GetString() : null;
}

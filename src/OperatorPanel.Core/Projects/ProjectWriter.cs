using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Writes a project as the file format the reader reads: indented, LF line ends, properties always in the same
/// order and always present (so files diff cleanly), camelCase words for enums, canonical address strings.
/// </summary>
internal static class ProjectWriter
{
    private static readonly JsonWriterOptions Options = new()
    {
        Indented = true,
        NewLine = "\n",
        // Keeps alarm texts in any language readable in the file; the file is never embedded in HTML.
        Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping,
    };

    public static byte[] Write(PanelProject project)
    {
        ArgumentNullException.ThrowIfNull(project);
        using var buffer = new MemoryStream();
        using (var json = new Utf8JsonWriter(buffer, Options))
        {
            json.WriteStartObject();
            json.WriteNumber("schemaVersion", ProjectFile.SchemaVersion);
            json.WriteString("name", project.Name);
            json.WriteStartObject("refresh");
            json.WriteString("mode", RefreshModeWords.Of(project.Refresh.Mode));
            json.WriteNumber("minimumPeriodMs", (int)project.Refresh.MinimumPeriod.TotalMilliseconds);
            json.WriteEndObject();
            WriteHistory(json, project.History);
            json.WriteBoolean("alarmSound", project.AlarmSound);
            json.WriteStartArray("stations");
            foreach (var station in project.Stations)
            {
                WriteStation(json, station);
            }

            json.WriteEndArray();
            json.WriteEndObject();
        }

        buffer.WriteByte((byte)'\n');
        return buffer.ToArray();
    }

    public static string WriteText(PanelProject project) => Encoding.UTF8.GetString(Write(project));

    private static void WriteStation(Utf8JsonWriter json, ProjectStation station)
    {
        json.WriteStartObject();
        json.WriteString("name", station.Name);
        json.WriteNumber("address", station.Address.Address);
        json.WriteStartObject("cpu");
        json.WriteString("model", CpuModelNames.ShortName(station.Cpu.Model));
        json.WriteString("revision", JsonWords.Of(station.Cpu.Revision));
        json.WriteEndObject();
        json.WriteStartObject("link");
        json.WriteString("port", station.Link.PortName);
        json.WriteNumber("baud", station.Link.BaudRate);
        json.WriteString("parity", JsonWords.Of(station.Link.Parity));
        json.WriteNumber("dataBits", station.Link.DataBits);
        json.WriteNumber("stopBits", station.Link.StopBits);
        json.WriteString("kind", JsonWords.Of(station.Link.Kind));
        if (station.Link.Protocol != LinkProtocol.Freeport)
        {
            // Written only when not the default, so a Freeport project's file stays as it always was.
            json.WriteString("protocol", JsonWords.Of(station.Link.Protocol));
        }
        json.WriteEndObject();
        json.WriteBoolean("allowStop", station.AllowStop);
        if (station.Compact)
        {
            // Written only when set, so a project with the full handler keeps the file it always had.
            json.WriteBoolean("compact", true);
        }

        if (station.HandlerVFirst is { } vFirst)
        {
            // Written only when set: absent is the default place, and files without it stay as they were.
            json.WriteNumber(HandlerVFirstReader.Name, vFirst);
        }

        WriteSymbols(json, "inputs", station.Inputs);
        WriteSymbols(json, "outputs", station.Outputs);
        json.WriteStartArray("tags");
        foreach (var tag in station.Tags)
        {
            json.WriteStartObject();
            json.WriteString("symbol", tag.Symbol);
            json.WriteString("address", tag.Address.ToString());
            json.WriteString("format", JsonWords.Of(tag.Format));
            json.WriteBoolean("writable", tag.Writable);
            json.WriteString("description", tag.Description);
            WriteEngineering(json, tag);
            json.WriteBoolean("record", tag.Recorded);
            // Written only when set: absent means the project's deadband, and a file full of nulls reads as unfinished.
            if (tag.Deadband is { } deadband)
            {
                json.WriteNumber("deadband", deadband);
            }

            json.WriteEndObject();
        }

        json.WriteEndArray();
        json.WriteStartArray("alarms");
        foreach (var alarm in station.Alarms)
        {
            json.WriteStartObject();
            json.WriteString("flag", alarm.Flag.ToString());
            json.WriteString("text", alarm.Text);
            json.WriteString("class", JsonWords.Of(alarm.Class));
            json.WriteBoolean("acknowledgementRequired", alarm.AcknowledgementRequired);
            json.WriteEndObject();
        }

        json.WriteEndArray();
        json.WriteEndObject();
    }

    /// <summary>
    /// Unit, scale and range only when set: unlike the other properties they are left out when absent, so a project
    /// written before them saves exactly as it was.
    /// </summary>
    private static void WriteEngineering(Utf8JsonWriter json, ProjectTag tag)
    {
        if (tag.Unit is { } unit)
        {
            json.WriteString("unit", unit);
        }

        if (tag.Scale is { } scale)
        {
            json.WriteStartObject("scale");
            json.WriteNumber("rawLow", scale.RawLow);
            json.WriteNumber("rawHigh", scale.RawHigh);
            json.WriteNumber("low", scale.Low);
            json.WriteNumber("high", scale.High);
            json.WriteEndObject();
        }

        if (tag.Range?.Min is { } min)
        {
            json.WriteNumber("min", min);
        }

        if (tag.Range?.Max is { } max)
        {
            json.WriteNumber("max", max);
        }
    }

    private static void WriteHistory(Utf8JsonWriter json, HistorySettings history)
    {
        json.WriteStartObject("history");
        json.WriteBoolean("enabled", history.Enabled);
        json.WriteNumber("deadbandPercent", history.DeadbandPercent);
        json.WriteNumber("samplePeriodS", (int)history.SamplePeriod.TotalSeconds);
        json.WriteNumber("retentionDays", history.RetentionDays);
        json.WriteNumber("maxSizeMb", history.MaxSizeMb);
        json.WriteEndObject();
    }

    private static void WriteSymbols(Utf8JsonWriter json, string name, IEnumerable<IoSymbol> symbols)
    {
        json.WriteStartArray(name);
        foreach (var symbol in symbols)
        {
            json.WriteStartObject();
            json.WriteString("symbol", symbol.Symbol);
            json.WriteString("address", symbol.Address.ToString());
            json.WriteString("description", symbol.Description);
            json.WriteEndObject();
        }

        json.WriteEndArray();
    }
}

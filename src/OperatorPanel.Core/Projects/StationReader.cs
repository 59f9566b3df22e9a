using System.Collections.Immutable;
using System.Globalization;
using System.Text.Json;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads the <c>stations</c> array, then checks the stations against each other: unique names, and on each serial
/// port unique station addresses and one set of line settings (the stations on a port share one RS-485 bus).
/// </summary>
internal static class StationReader
{
    public static ImmutableArray<ProjectStation>? ReadAll(JsonFields project, ProjectProblems problems)
    {
        var elements = project.Array("stations", required: true);
        if (elements is null)
        {
            return null;
        }

        if (elements.Count == 0)
        {
            project.Problem("stations", "a project needs at least one station");
            return null;
        }

        var stations = new List<ProjectStation>();
        var names = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        var buses = new Dictionary<string, Bus>(StringComparer.OrdinalIgnoreCase);
        foreach (var (element, path) in elements)
        {
            if (problems.IsFull)
            {
                return null;
            }

            var station = Read(element, path, problems, out var keys);
            if (keys is not null)
            {
                CheckAgainstOthers(keys, names, buses);
            }

            if (station is not null)
            {
                stations.Add(station);
            }
        }

        return stations.Count == elements.Count ? [.. stations] : null;
    }

    private static ProjectStation? Read(JsonElement element, string path, ProjectProblems problems, out StationKeys? keys)
    {
        keys = null;
        var fields = JsonFields.Open(element, path, problems);
        if (fields is null)
        {
            return null;
        }

        fields.ReportUnknown("name", "address", "cpu", "link", "allowStop", "compact", "handlerVFirst", "inputs", "outputs", "tags", "alarms");
        var name = TextRule.StationName.Read(fields, "name");
        if (name is not null && string.IsNullOrWhiteSpace(name))
        {
            fields.Problem("name", "the station name is empty");
            name = null;
        }

        var address = ReadAddress(fields);
        var cpu = CpuReader.Read(fields.Object("cpu"));
        var link = LinkReader.Read(fields.Object("link"), cpu);
        var allowStop = fields.Bool("allowStop", fallback: false);
        var compact = fields.Bool("compact", fallback: false);
        var vFirstOk = HandlerVFirstReader.TryRead(fields, cpu, compact, out var vFirst);
        keys = new StationKeys(fields, name, address, link);

        var registry = new EntryRegistry();
        var inputs = IoSymbolReader.ReadAll(fields, "inputs", MemoryArea.I, cpu, registry);
        var outputs = IoSymbolReader.ReadAll(fields, "outputs", MemoryArea.Q, cpu, registry);
        var tags = TagReader.ReadAll(fields, cpu, link?.Protocol, registry);
        var alarms = AlarmReader.ReadAll(fields, cpu, link?.Protocol, registry);
        if (name is null || address is null || cpu is null || link is null || allowStop is null || compact is null || inputs is null || outputs is null || tags is null || alarms is null || !vFirstOk)
        {
            return null;
        }

        return new ProjectStation(name, address.Value, cpu, link, inputs.Value, outputs.Value, tags.Value, alarms.Value)
        {
            AllowStop = allowStop.Value,
            Compact = compact.Value,
            HandlerVFirst = vFirst,
        };
    }

    private static Station? ReadAddress(JsonFields fields)
    {
        var number = fields.Int("address");
        if (number is not { } n)
        {
            return null;
        }

        if (!Station.TryCreate(n, out var station, out var error))
        {
            fields.Problem("address", error);
            return null;
        }

        return station;
    }

    private static void CheckAgainstOthers(StationKeys keys, Dictionary<string, string> names, Dictionary<string, Bus> buses)
    {
        if (keys.Name is { } name && !names.TryAdd(name.Trim(), keys.Fields.Path))
        {
            keys.Fields.Problem("name", $"station name '{JsonPath.Shorten(name)}' is already used by {names[name.Trim()]}");
        }

        if (keys.Link is not { } link)
        {
            return;
        }

        if (!buses.TryGetValue(link.PortName.Trim(), out var bus))
        {
            bus = new Bus(link, keys.Fields.Path);
            buses.Add(link.PortName.Trim(), bus);
        }
        else if (!SameLine(bus.Settings, link))
        {
            keys.Fields.Problem("link", $"{JsonPath.Shorten(link.PortName)} is set to {LinkReader.Describe(bus.Settings)} by {bus.FirstPath}; "
                + "the stations on one port share one bus and its settings");
        }

        if (keys.Address is { } address && !bus.Addresses.TryAdd(address.Address, keys.Fields.Path))
        {
            keys.Fields.Problem("address", string.Create(CultureInfo.InvariantCulture,
                $"station address {address.Address} is already used on {JsonPath.Shorten(link.PortName)} by {bus.Addresses[address.Address]}"));
        }
    }

    private static bool SameLine(SerialSettings a, SerialSettings b) =>
        a.BaudRate == b.BaudRate && a.Parity == b.Parity && a.DataBits == b.DataBits && a.StopBits == b.StopBits && a.Kind == b.Kind && a.Protocol == b.Protocol;

    private sealed record StationKeys(JsonFields Fields, string? Name, Station? Address, SerialSettings? Link);

    private sealed record Bus(SerialSettings Settings, string FirstPath)
    {
        public Dictionary<int, string> Addresses { get; } = [];
    }
}

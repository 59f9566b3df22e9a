using System.Text.Json.Nodes;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>Edits of a project tree that need more than one line.</summary>
internal static class ProjectTreeExtensions
{
    /// <summary>Appends a CPU 224 station with no I/O, tags or alarms, 9600 8N1 on <paramref name="port"/>.</summary>
    public static JsonObject AddStation(this JsonObject tree, string name, int address, string port)
    {
        var station = new JsonObject
        {
            ["name"] = name,
            ["address"] = address,
            ["cpu"] = new JsonObject { ["model"] = "224" },
            ["link"] = new JsonObject { ["port"] = port },
        };
        tree["stations"]!.AsArray().Add(station);
        return station;
    }
}

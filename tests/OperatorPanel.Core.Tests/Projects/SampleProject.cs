using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>samples/bottling-line.opproj, found by walking up from the test binaries to the solution folder.</summary>
internal static class SampleProject
{
    public static string Path { get; } = Locate();

    public static string Text { get; } = File.ReadAllText(Path);

    /// <summary>The sample as a mutable tree; each call returns a fresh copy.</summary>
    public static JsonObject Tree() => JsonNode.Parse(Text)!.AsObject();

    public static JsonObject Station(this JsonObject tree) => tree["stations"]![0]!.AsObject();

    private static string Locate()
    {
        for (var folder = new DirectoryInfo(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            var candidate = System.IO.Path.Combine(folder.FullName, "samples", "bottling-line.opproj");
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }

        throw new FileNotFoundException("samples/bottling-line.opproj not found above " + AppContext.BaseDirectory);
    }
}

namespace OperatorPanel.Core.Projects;

/// <summary>
/// How one front end names a station's two handler settings in <see cref="CompactStop.Describe"/>: the project file's
/// properties, generate's options, the wizard's check boxes.
/// </summary>
/// <param name="Compact">The compact setting as it was given: <c>"compact": true</c>, <c>--compact</c>.</param>
/// <param name="AllowStop">The STOP setting as it was given: <c>"allowStop": true</c>, <c>--allow-stop</c>.</param>
/// <param name="CompactOff">How to clear the compact setting: <c>set "compact": false</c>.</param>
/// <param name="AllowStopOff">How to clear the STOP setting: <c>set "allowStop": false</c>.</param>
public sealed record CompactStopWords(string Compact, string AllowStop, string CompactOff, string AllowStopOff)
{
    /// <summary>The project file's words.</summary>
    public static CompactStopWords File { get; } = new("\"compact\": true", "\"allowStop\": true", "set \"compact\": false", "set \"allowStop\": false");
}

using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Link.V3;

/// <summary>
/// What the panel says about a station whose handler is older than protocol v3 (v1 or v2: it ignores every v3 frame and
/// looks silent, and only a v2 or v1 IDENTIFY finds it), or whose IDENTIFY reply is not a v3 one.
/// </summary>
public static class HandlerBeforeV3
{
    public static string Message(Station station, string found) =>
        $"{station} runs {found}, but the panel speaks protocol v3: regenerate the PLC code (opanel generate) and download it";
}

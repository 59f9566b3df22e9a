using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Link;

/// <summary>
/// What the panel says about a station whose handler speaks protocol v1: it ignores every v2 frame (check characters
/// are not hex), so it looks silent, and only the v1 IDENTIFY probe (Protocol/V1/V1IdentifyProbe) finds it.
/// </summary>
public static class HandlerV1
{
    public static string Message(Station station) =>
        $"{station} runs Operator Panel handler protocol v1: regenerate the PLC code (opanel generate) and download it";
}

using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Cli.Watch;

/// <summary>
/// A station's IDENTIFY reply against its project entry, as watch shows it on the station's "handler" line: "ok: ..."
/// or "MISMATCH with CPU 226: ..." (docs/protocol-v2.md, "01 IDENTIFY"; the comparison is <see cref="IdentifyCheck"/>).
/// </summary>
internal static class HandlerCheck
{
    public static string Describe(ProjectStation station, PlcResponse reply)
    {
        if (reply is IdentifyResponse identity)
        {
            return IdentifyCheck.Mismatch(identity, station.Cpu) is { } mismatch
                ? $"MISMATCH with {station.Cpu.DisplayName}: {mismatch}"
                : $"ok: generated for {IdentifyCheck.DescribeGeneratedFor(identity)}, protocol {identity.ProtocolVersion}{Shape(identity.V3Identity)}, mode switch {(identity.ModeSwitchRun ? "RUN" : "TERM")}";
        }

        // Any other reply to IDENTIFY: an ErrorResponse from a handler that is not ours, or another device's answer.
        return reply is ErrorResponse refused
            ? $"IDENTIFY refused ({refused.Error}): the handler is not ours or too old; regenerate it"
            : $"IDENTIFY answered with a {reply.Command} reply: another device on the bus?";
    }

    /// <summary>
    /// A v3 handler's shape as IDENTIFY reports it (docs/protocol.md section 6): the compact one reads 16 bytes a request,
    /// the full one a whole list in one; nothing for an older reply.
    /// </summary>
    private static string Shape(Core.Protocol.V3.Identity? v3) => v3 switch
    {
        null => string.Empty,
        { HasList: false } => $", compact handler (no list: READs of {v3.MaxData} bytes)",
        _ => $", full handler (list of {v3.ListItems} items, {v3.ListBytes} bytes{(v3.HasStop ? ", STOP" : string.Empty)})",
    };
}

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
                : $"ok: generated for {IdentifyCheck.DescribeGeneratedFor(identity)}, protocol {identity.ProtocolVersion}{Shape(identity.V3Identity)}, mode switch {(identity.ModeSwitchRun ? "RUN" : "TERM")}"
                    + Place(station, identity.V3Identity);
        }

        // Any other reply to IDENTIFY: an ErrorResponse from a handler that is not ours, or another device's answer.
        return reply is ErrorResponse refused
            ? $"IDENTIFY refused ({refused.Error}): the handler is not ours or too old; regenerate it"
            : $"IDENTIFY answered with a {reply.Command} reply: another device on the bus?";
    }

    /// <summary>
    /// Nothing when the handler's V bytes (IDENTIFY's V_FIRST and V_BYTES) are where the project puts them
    /// ("handlerVFirst", "compact"); otherwise both ranges and the fix: the panel refuses writes to the project's range
    /// (Core WriteRules), so a handler generated elsewhere (generate --buffer without the project saying so) leaves the
    /// user's own bytes refused and the handler's bytes to its own 83.
    /// </summary>
    private static string Place(ProjectStation station, Core.Protocol.V3.Identity? v3)
    {
        if (v3 is null || HandlerProtection.OwnVBytes(station.Cpu, station.Compact, station.HandlerVFirst) is not var (first, last))
        {
            return string.Empty;
        }

        var (actualFirst, actualLast) = (v3.VFirst, v3.VFirst + v3.VBytes - 1);
        return actualFirst == first && actualLast == last
            ? string.Empty
            : $"; but its V bytes are VB{actualFirst}-VB{actualLast} and the project's VB{first}-VB{last} (the bytes the panel refuses to write): "
                + $"set \"handlerVFirst\": {actualFirst}{(v3.HasList == station.Compact ? $" and \"compact\": {(!v3.HasList).ToString().ToLowerInvariant()}" : string.Empty)} in the project, or regenerate the handler from it";
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

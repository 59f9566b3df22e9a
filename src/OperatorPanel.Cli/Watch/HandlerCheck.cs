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
                : $"ok: generated for {IdentifyCheck.DescribeGeneratedFor(identity)}, protocol {identity.ProtocolVersion}, mode switch {(identity.ModeSwitchRun ? "RUN" : "TERM")}";
        }

        // Any other reply to IDENTIFY: an ErrorResponse from a handler that is not ours, or another device's answer.
        return reply is ErrorResponse refused
            ? $"IDENTIFY refused ({refused.Error}): the handler is not ours or too old; regenerate it"
            : $"IDENTIFY answered with a {reply.Command} reply: another device on the bus?";
    }
}

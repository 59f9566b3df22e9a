using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Cli.Link;

/// <summary>Addresses typed on the command line, checked before anything goes on the wire.</summary>
internal static class AddressArguments
{
    /// <summary>
    /// Parses <paramref name="text"/>: the target's link must reach its area (PPI reads S, AIW, AQW, T and C as well;
    /// Freeport does not: <see cref="LinkAreas"/>), and with a known CPU it must exist there (and be writable over that
    /// link for <see cref="AddressUse.Write"/>). Inputs are never written, CPU known or not.
    /// </summary>
    public static bool TryParse(string? text, CpuProfile? cpu, LinkProtocol link, AddressUse use, out PlcAddress address, [NotNullWhen(false)] out string? error)
    {
        if (!PlcAddress.TryParse(text, out address, out var parseError))
        {
            error = parseError.Message;
            return false;
        }

        error = LinkAreas.Refusal(address, link, cpu, use);
        return error is null;
    }
}

using System.Diagnostics.CodeAnalysis;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Cli.Link;

/// <summary>Addresses typed on the command line, checked before anything goes on the wire.</summary>
internal static class AddressArguments
{
    /// <summary>
    /// Parses <paramref name="text"/>: the link must serve its area, and with a known CPU it must exist there (and be
    /// writable for <see cref="AddressUse.Write"/>).
    /// </summary>
    public static bool TryParse(string? text, CpuProfile? cpu, AddressUse use, out PlcAddress address, [NotNullWhen(false)] out string? error)
    {
        if (!PlcAddress.TryParse(text, out address, out var parseError))
        {
            error = parseError.Message;
            return false;
        }

        if (LinkAreas.FreeportRefusal(address) is { } notServed)
        {
            error = notServed;
            return false;
        }

        if (use == AddressUse.Write && address.Area == MemoryArea.I)
        {
            // The handler's write mask never has I (docs/protocol.md): refused here, before anything is read or sent.
            error = $"{address}: inputs are the field's; the Freeport link writes only {LinkAreas.FreeportWritten}";
            return false;
        }

        error = cpu is null ? null : AddressRules.Check(address, cpu, use)?.Message;
        return error is null;
    }
}

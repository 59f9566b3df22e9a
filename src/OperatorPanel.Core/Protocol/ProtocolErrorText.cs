using System.Collections.Frozen;

namespace OperatorPanel.Core.Protocol;

/// <summary>
/// What a refusal means, in words for the operator, under the protocol 3 STATUS the station sent (docs/protocol.md
/// section 3: 82-87; the link hands them on as <see cref="ProtocolError"/> 02-07). A v3 handler never answers a bad frame
/// check: it stays silent.
/// </summary>
public static class ProtocolErrorText
{
    private static readonly FrozenDictionary<ProtocolError, string> Texts = new Dictionary<ProtocolError, string>
    {
        [ProtocolError.None] = "no error",
        [ProtocolError.BadChecksum] = "the frame check did not match",
        [ProtocolError.AddressOutOfRange] = "82: unknown area, or past the end of the area on this CPU",
        [ProtocolError.NotWritable] = "83: the PLC refuses writes there (inputs, SM, an area the handler's write mask leaves out, "
            + "or the handler's own V bytes)",
        [ProtocolError.BadLength] = "84: a length outside the protocol's limits",
        [ProtocolError.UnknownCommand] = "85: unknown command (STOP in a handler generated without it, or a list command in a compact handler)",
        [ProtocolError.BadParameter] = "86: a parameter out of range (STOP's payload)",
        [ProtocolError.ListNotDefined] = "87: no list is defined in the PLC (it restarted, or its switch or mode changed)",
    }.ToFrozenDictionary();

    public static string Describe(ProtocolError error) =>
        Texts.TryGetValue(error, out var text) ? text : $"{(byte)error | 0x80:X2}";
}

using System.Collections.Frozen;

namespace OperatorPanel.Core.Protocol;

/// <summary>What an error reply means, in words for the operator (docs/protocol-v2.md section 3).</summary>
public static class ProtocolErrorText
{
    private static readonly FrozenDictionary<ProtocolError, string> Texts = new Dictionary<ProtocolError, string>
    {
        [ProtocolError.None] = "no error",
        [ProtocolError.BadChecksum] = "error 01: the frame check did not match",
        [ProtocolError.AddressOutOfRange] = "error 02: unknown area, or past the end of the area on this CPU",
        [ProtocolError.NotWritable] = "error 03: the PLC refuses writes there (inputs, an area without write access, "
            + "protected SM bytes, or the handler's own V bytes: its buffer and work bytes)",
        [ProtocolError.BadLength] = "error 04: a length or item count outside the protocol's limits",
        [ProtocolError.UnknownCommand] = "error 05: unknown command (or STOP in a handler generated without it)",
        [ProtocolError.BadParameter] = "error 06: bit number, value, list number, flags or STOP payload out of range",
        [ProtocolError.ListNotDefined] = "error 07: the list is not defined in the PLC",
    }.ToFrozenDictionary();

    public static string Describe(ProtocolError error) =>
        Texts.TryGetValue(error, out var text) ? text : $"error {(byte)error:X2}";
}

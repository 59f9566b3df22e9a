using System.Buffers.Binary;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The S7 PDU header (libnodave doc/pdu.html): 16#32, message type, two reserved bytes, PDU reference, parameter length,
/// data length (all big-endian), and for <see cref="S7MessageType.Ack"/> and <see cref="S7MessageType.AckData"/> the
/// error class and error code (libnodave doc/PDUerrorcodes.html: 16#8500 "incorrect PDU size" ...).
/// </summary>
public readonly record struct S7Header(S7MessageType Type, ushort Reference, int ParameterLength, int DataLength, byte ErrorClass = 0, byte ErrorCode = 0)
{
    public const byte ProtocolId = 0x32;
    public const int JobLength = 10;
    public const int AnswerLength = 12;

    public int Length => Type is S7MessageType.Ack or S7MessageType.AckData ? AnswerLength : JobLength;

    public int PduLength => Length + ParameterLength + DataLength;

    /// <summary>Error class and code as one number, as libnodave prints them (16#8104).</summary>
    public int Error => (ErrorClass << 8) | ErrorCode;

    public void WriteTo(Span<byte> pdu)
    {
        pdu[0] = ProtocolId;
        pdu[1] = (byte)Type;
        pdu[2] = 0;
        pdu[3] = 0;
        BinaryPrimitives.WriteUInt16BigEndian(pdu[4..], Reference);
        BinaryPrimitives.WriteUInt16BigEndian(pdu[6..], (ushort)ParameterLength);
        BinaryPrimitives.WriteUInt16BigEndian(pdu[8..], (ushort)DataLength);
        if (Length == AnswerLength)
        {
            pdu[10] = ErrorClass;
            pdu[11] = ErrorCode;
        }
    }

    /// <summary>A whole PDU: this header (its lengths are those of <paramref name="parameters"/> and <paramref name="data"/>), then both.</summary>
    public static byte[] Pdu(S7MessageType type, ushort reference, byte[] parameters, byte[] data)
    {
        ArgumentNullException.ThrowIfNull(parameters);
        ArgumentNullException.ThrowIfNull(data);
        var header = new S7Header(type, reference, parameters.Length, data.Length);
        var pdu = new byte[header.PduLength];
        header.WriteTo(pdu);
        parameters.CopyTo(pdu, header.Length);
        data.CopyTo(pdu, header.Length + parameters.Length);
        return pdu;
    }

    /// <summary>Reads a header and checks that its lengths cover exactly <paramref name="pdu"/>.</summary>
    public static bool TryRead(ReadOnlySpan<byte> pdu, out S7Header header, out S7PduError error)
    {
        header = default;
        if (pdu.Length < JobLength)
        {
            error = S7PduError.TooShort;
            return false;
        }

        if (pdu[0] != ProtocolId)
        {
            error = S7PduError.NotS7;
            return false;
        }

        var type = (S7MessageType)pdu[1];
        var answer = type is S7MessageType.Ack or S7MessageType.AckData;
        if (answer && pdu.Length < AnswerLength)
        {
            error = S7PduError.TooShort;
            return false;
        }

        header = new S7Header(
            type,
            BinaryPrimitives.ReadUInt16BigEndian(pdu[4..]),
            BinaryPrimitives.ReadUInt16BigEndian(pdu[6..]),
            BinaryPrimitives.ReadUInt16BigEndian(pdu[8..]),
            answer ? pdu[10] : (byte)0,
            answer ? pdu[11] : (byte)0);
        error = header.PduLength == pdu.Length ? S7PduError.None
            : header.PduLength > pdu.Length ? S7PduError.TooShort
            : S7PduError.LengthMismatch;
        return error == S7PduError.None;
    }
}

using System.Text;
using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Protocol.V1;

/// <summary>
/// The one protocol-v1 exchange the panel still speaks: IDENTIFY with v1's XOR block check, sent only when a station
/// does not answer IDENTIFY v2, to tell a v1 handler ("regenerate the PLC code") from a silent station
/// (docs/protocol-v2.md, "Version 1 handlers"). v1 frame: '&lt;' STATION SEQ CMD PAYLOAD BCC '&gt;' as hex pairs, BCC = XOR of
/// the ASCII codes of the body characters before it. A v2 handler never answers this probe (its last four characters
/// are hex digits, not check characters), and a v1 handler never answers a v2 frame (check characters are not hex).
/// </summary>
public static class V1IdentifyProbe
{
    /// <summary>The bytes of a v1 IDENTIFY reply after STATUS: PROTOCOL_VERSION first.</summary>
    private const int V1IdentifyPayloadBytes = 15;

    /// <summary>The v1 IDENTIFY request to <paramref name="station"/>: "&lt;SSQQ01BB&gt;", 10 characters.</summary>
    public static byte[] Encode(Station station, byte sequence) =>
        Frame([(byte)station.Address, sequence, (byte)CommandCode.Identify]);

    /// <summary>
    /// True when <paramref name="frameChars"/> is a valid v1 IDENTIFY reply (STATUS 00, 15 payload bytes) from
    /// <paramref name="station"/> under <paramref name="sequence"/>; <paramref name="protocolVersion"/> is its first
    /// payload byte (1 for every v1 handler).
    /// </summary>
    public static bool TryDecodeReply(ReadOnlySpan<byte> frameChars, Station station, byte sequence, out byte protocolVersion)
    {
        protocolVersion = 0;
        if (frameChars.Length < 4 || frameChars[0] != FrameCodec.StartChar || frameChars[^1] != FrameCodec.EndChar)
        {
            return false;
        }

        var body = frameChars[1..^1];
        if (body.Length != 2 * (4 + 1 + V1IdentifyPayloadBytes) || !IsHex(body))
        {
            return false;
        }

        var bytes = Convert.FromHexString(Encoding.ASCII.GetString(body));
        if (Xor(body[..^2]) != bytes[^1] || bytes[0] != station.Address || bytes[1] != sequence
            || bytes[2] != ((byte)CommandCode.Identify | FreeportFrame.ReplyBit) || bytes[3] != 0)
        {
            return false;
        }

        protocolVersion = bytes[4];
        return true;
    }

    /// <summary>A v1 frame around <paramref name="bytes"/> (tests build v1 replies with it).</summary>
    public static byte[] Frame(ReadOnlySpan<byte> bytes)
    {
        var body = Encoding.ASCII.GetBytes(Convert.ToHexString(bytes));
        var bcc = Encoding.ASCII.GetBytes(Xor(body).ToString("X2", System.Globalization.CultureInfo.InvariantCulture));
        return [FrameCodec.StartChar, .. body, .. bcc, FrameCodec.EndChar];
    }

    private static bool IsHex(ReadOnlySpan<byte> body)
    {
        foreach (var c in body)
        {
            if (!HexAscii.IsDigit(c))
            {
                return false;
            }
        }

        return true;
    }

    private static byte Xor(ReadOnlySpan<byte> characters)
    {
        byte bcc = 0;
        foreach (var c in characters)
        {
            bcc ^= c;
        }

        return bcc;
    }
}

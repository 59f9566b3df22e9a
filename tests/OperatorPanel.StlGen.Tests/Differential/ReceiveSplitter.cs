namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// What the handler's RCV (start '&lt;', end '&gt;', 255 characters at most, optional inter-character timer) makes of
/// the characters on the line: the messages as they land in the receive buffer, which is what the reference model's
/// HandleFrame takes. Characters outside a message are dropped; a second '&lt;' inside a message is just a character
/// (ReceiveMessage in Simulator/Stl/Freeport). Gaps are either 0 or well past the timeout, so no timing edge is tested.
/// </summary>
internal static class ReceiveSplitter
{
    private const int MaxCount = 255;

    public static List<byte[]> Split(IReadOnlyList<WireChunk> chunks, int charTimeoutMs)
    {
        var messages = new List<byte[]>();
        List<byte>? message = null;
        foreach (var chunk in chunks)
        {
            if (message is not null && charTimeoutMs > 0 && chunk.GapBefore > TimeSpan.FromMilliseconds(charTimeoutMs))
            {
                messages.Add([.. message]);
                message = null;
            }

            foreach (var c in chunk.Characters)
            {
                if (message is null)
                {
                    message = c == '<' ? [c] : null;
                    continue;
                }

                message.Add(c);
                if (c == '>' || message.Count >= MaxCount)
                {
                    messages.Add([.. message]);
                    message = null;
                }
            }
        }

        if (message is not null && charTimeoutMs > 0)
        {
            messages.Add([.. message]);
        }

        return messages;
    }
}

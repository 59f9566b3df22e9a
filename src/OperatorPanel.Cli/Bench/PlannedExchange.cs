namespace OperatorPanel.Cli.Bench;

/// <summary>One request of a refresh cycle as Core encodes it, and the length of the reply Core expects for it.</summary>
internal sealed record PlannedExchange(string Name, byte[] Request, int ReplyChars)
{
    public int RequestChars => Request.Length;

    public int Chars => RequestChars + ReplyChars;
}

namespace OperatorPanel.Simulator.Hosting;

/// <summary>The program of a CPU that has none of ours: OB1 with one network that does nothing (NOP 0), as Micro/WIN exports it.</summary>
public static class EmptyProgram
{
    public const string Awl = "ORGANIZATION_BLOCK MAIN:OB1\r\nBEGIN\r\nNetwork 1\r\nNOP 0\r\nEND_ORGANIZATION_BLOCK\r\n";
}

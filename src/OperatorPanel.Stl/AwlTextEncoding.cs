namespace OperatorPanel.Stl;

/// <summary>The encoding <see cref="AwlSource.Decode"/> found for an .awl file.</summary>
public enum AwlTextEncoding
{
    Ascii,
    Utf8,
    Utf8WithByteOrderMark,
    Windows1252,
    Gbk,
}
